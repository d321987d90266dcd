#include "frontend/float_literals.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace qs::frontend {

namespace {

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::string float_literals_as_float(const std::string& text) {
    std::string out;
    out.reserve(text.size() + text.size() / 8);
    const std::size_t n = text.size();
    std::size_t i = 0;
    while (i < n) {
        const char c = text[i];
        if (c == '/' && i + 1 < n && text[i + 1] == '/') {  // a line comment, as it is
            const std::size_t end = text.find('\n', i);
            const std::size_t stop = end == std::string::npos ? n : end;
            out.append(text, i, stop - i);
            i = stop;
            continue;
        }
        if (c == '/' && i + 1 < n && text[i + 1] == '*') {  // a block comment, as it is
            const std::size_t end = text.find("*/", i + 2);
            const std::size_t stop = end == std::string::npos ? n : end + 2;
            out.append(text, i, stop - i);
            i = stop;
            continue;
        }
        const bool starts_number = digit(c) || (c == '.' && i + 1 < n && digit(text[i + 1]));
        if (!starts_number || (i > 0 && (identifier_char(text[i - 1]) || text[i - 1] == '.'))) {
            out += c;
            ++i;
            continue;
        }
        // A preprocessing number: digits, a point, an exponent with its sign, letters.
        std::size_t j = i;
        while (j < n && (identifier_char(text[j]) || text[j] == '.' ||
                         ((text[j] == '+' || text[j] == '-') && (text[j - 1] == 'e' || text[j - 1] == 'E')))) {
            ++j;
        }
        const std::string token = text.substr(i, j - i);
        i = j;
        const bool hex = token.size() > 1 && token[0] == '0' && (token[1] == 'x' || token[1] == 'X');
        const bool point_or_exponent = token.find_first_of(".eE") != std::string::npos;
        const bool is_double = token.size() > 2 && (token.ends_with("lf") || token.ends_with("LF"));
        if (hex || !point_or_exponent || is_double) {
            out += token;
            continue;
        }
        std::string digits = token;
        std::string suffix;
        if (digits.back() == 'f' || digits.back() == 'F') suffix = digits.back(), digits.pop_back();
        char* end = nullptr;
        const float value = std::strtof(digits.c_str(), &end);
        if (end != digits.c_str() + digits.size() || !std::isfinite(value)) {
            out += token;  // not a literal this reads (glslang says what is wrong with it)
            continue;
        }
        char exact[40];
        std::snprintf(exact, sizeof exact, "%.17g", double(value));
        std::string written = exact;
        if (written.find_first_of(".eEn") == std::string::npos) written += ".0";  // still a float literal
        out += written + suffix;
    }
    return out;
}

}  // namespace qs::frontend
