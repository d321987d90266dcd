#include "piglit/skip_reason.h"

#include <cctype>
#include <regex>

namespace qs::piglit {

namespace {

// A quoted word that is GLSL's own (a type, a built-in) rather than one of the shader's names.
bool glsl_word(const std::string& w) {
    static const std::regex own(
        "gl_.*|(void|bool|int|uint|float|double|[biud]?vec[234]|d?mat[234](x[234])?|atomic_uint|[iu]?(sampler|image|texture)\\w*|"
        "struct)(\\[\\d*\\])?|[a-z]+[A-Z]\\w*\\(.*|[a-zA-Z]+\\(\\)");
    return std::regex_match(w, own);
}

}  // namespace

std::string skip_reason_of(const std::string& message, const std::string& file) {
    std::string m = message.substr(0, message.find('\n'));
    // FILE:LINE:COL: (each part optional after FILE)
    if (m.rfind(file, 0) == 0) {
        std::size_t at = file.size();
        while (at < m.size() && (m[at] == ':' || std::isdigit(static_cast<unsigned char>(m[at])))) ++at;
        while (at < m.size() && m[at] == ' ') ++at;
        m = m.substr(at);
    }
    // Another program's name in front ("NAME: the shaders pass ...").
    if (m.rfind(file + ": ", 0) == 0) m = m.substr(file.size() + 2);
    std::string out;
    for (std::size_t i = 0; i < m.size(); ++i) {
        if (m[i] != '\'') {
            out += m[i];
            continue;
        }
        const std::size_t close = m.find('\'', i + 1);
        if (close == std::string::npos) {
            out += m.substr(i);
            break;
        }
        const std::string word = m.substr(i + 1, close - i - 1);
        out += "'" + (glsl_word(word) ? word : std::string("...")) + "'";
        i = close;
    }
    // Numbers in counts ("pass 12 varying floats") vary from test to test.
    out = std::regex_replace(out, std::regex("\\b\\d+ varying floats"), "N varying floats");
    return "GLSL: " + out;
}

}  // namespace qs::piglit
