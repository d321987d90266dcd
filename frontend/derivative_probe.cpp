#include "frontend/derivative_probe.h"

#include <cctype>
#include <sstream>

#include "frontend/glsl_error.h"

namespace qs::frontend {

namespace {

bool identifier_char(char c) { return std::isalnum((unsigned char)c) || c == '_'; }

std::string named(const DerivativeProbe& p) { return p.option + " \"" + p.expression + "\": "; }

// Refuses (GlslError) a text that could be anything but one expression between parentheses.
void check_expression(const DerivativeProbe& p) {
    const std::string& e = p.expression;
    if (e.find_first_not_of(" \t") == std::string::npos) throw GlslError(p.option + ": error: an empty expression");
    int depth = 0;
    for (std::size_t i = 0; i < e.size(); ++i) {
        const char c = e[i];
        if (!std::isprint((unsigned char)c) && c != '\t') {
            throw GlslError(p.option + ": error: the expression holds a character that is not printable ASCII (byte " +
                            std::to_string(int((unsigned char)c)) + " at offset " + std::to_string(i) + ")");
        }
        if (c == ';' || c == '{' || c == '}' || c == '#' || c == '\\') {
            throw GlslError(named(p) + "error: '" + std::string(1, c) + "' at offset " + std::to_string(i) +
                            ": one GLSL expression is wanted, not statements, blocks or directives");
        }
        if (c == '/' && i + 1 < e.size() && (e[i + 1] == '/' || e[i + 1] == '*')) {
            throw GlslError(named(p) + "error: a comment at offset " + std::to_string(i) +
                            ": one GLSL expression is wanted");
        }
        depth += c == '(' ? 1 : c == ')' ? -1 : 0;
        if (depth < 0) throw GlslError(named(p) + "error: ')' at offset " + std::to_string(i) + " closes nothing");
    }
    if (depth != 0) throw GlslError(named(p) + "error: a '(' is not closed");
}

// The offset of the '}' that closes main's body in preprocessed text, where every brace is the
// code's own (no comments; directive lines hold none that count).
std::size_t end_of_main(const std::string& file, const std::string& text) {
    int depth = 0;
    bool line_start = true;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') {
            line_start = true;
            continue;
        }
        if (line_start && c == '#') {  // a directive: skip to its line's end
            i = text.find('\n', i);
            if (i == std::string::npos) break;
            --i;
            continue;
        }
        if (c != ' ' && c != '\t' && c != '\r') line_start = false;
        if (c == '{') ++depth;
        if (c == '}') --depth;
        if (depth != 0 || text.compare(i, 4, "main") != 0 || (i > 0 && identifier_char(text[i - 1])) ||
            (i + 4 < text.size() && identifier_char(text[i + 4]))) {
            continue;
        }
        // `main` at file scope: a definition when its parameter list is followed by a body.
        std::size_t j = text.find_first_not_of(" \t\r\n", i + 4);
        if (j == std::string::npos || text[j] != '(') continue;
        j = text.find(')', j);
        if (j == std::string::npos) break;
        j = text.find_first_not_of(" \t\r\n", j + 1);
        if (j == std::string::npos || text[j] != '{') continue;
        int body = 0;
        for (std::size_t k = j; k < text.size(); ++k) {
            if (text[k] == '{') ++body;
            if (text[k] == '}' && --body == 0) return k;
        }
        break;
    }
    throw GlslError(file + ": error: no body of main() to evaluate an expression at the end of");
}

}  // namespace

ProbedSource probed_source(const std::string& file, const std::string& preprocessed, const DerivativeProbe& probe) {
    check_expression(probe);
    const std::size_t end = end_of_main(file, preprocessed);
    ProbedSource s;
    s.strings = {preprocessed.substr(0, end), " (" + probe.expression + ");\n", preprocessed.substr(end)};
    s.names = {file, probe.option, file};
    return s;
}

std::string probe_messages(const std::string& messages, const DerivativeProbe& probe) {
    std::istringstream in(messages);
    std::string line, out;
    const std::string prefix = probe.option + ":";
    while (std::getline(in, line)) {
        if (line.rfind(prefix, 0) == 0) {
            // OPTION:LINE:COL: rest -> OPTION "EXPRESSION": rest
            std::size_t at = prefix.size();
            for (int field = 0; field < 2 && at < line.size() && std::isdigit((unsigned char)line[at]); ++field) {
                while (at < line.size() && std::isdigit((unsigned char)line[at])) ++at;
                if (at < line.size() && line[at] == ':') ++at;
            }
            if (at < line.size() && line[at] == ' ') ++at;
            line = named(probe) + line.substr(at);
        }
        out += (out.empty() ? "" : "\n") + line;
    }
    return out;
}

}  // namespace qs::frontend
