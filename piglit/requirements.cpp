#include "piglit/requirements.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>

#include "shading/batches.h"
#include "shading/shader_uniforms.h"

namespace qs::piglit {

namespace {

enum class Comparison { Equal, NotEqual, Less, LessEqual, Greater, GreaterEqual };

bool compare(double required, double actual, Comparison c) {
    switch (c) {
        case Comparison::Equal: return actual == required;
        case Comparison::NotEqual: return actual != required;
        case Comparison::Less: return actual < required;
        case Comparison::LessEqual: return actual <= required;
        case Comparison::Greater: return actual > required;
        case Comparison::GreaterEqual: return actual >= required;
    }
    return false;
}

const char* comparison_text(Comparison c) {
    constexpr const char* t[] = {"==", "!=", "<", "<=", ">", ">="};
    return t[int(c)];
}

// A cursor over one line, with piglit's parse_str (leading blanks skipped, a literal prefix).
struct Cursor {
    std::string_view s;
    void skip_blanks() {
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s[0]))) s.remove_prefix(1);
    }
    bool take(std::string_view literal) {
        skip_blanks();
        if (s.substr(0, literal.size()) != literal) return false;
        s.remove_prefix(literal.size());
        return true;
    }
    bool comparison(Comparison& c) {
        // In piglit's order, so that "<=" is not read as "<".
        if (take("==")) c = Comparison::Equal;
        else if (take("!=")) c = Comparison::NotEqual;
        else if (take("<=")) c = Comparison::LessEqual;
        else if (take("<")) c = Comparison::Less;
        else if (take(">=")) c = Comparison::GreaterEqual;
        else if (take(">")) c = Comparison::Greater;
        else return false;
        return true;
    }
    bool unsigned_number(int& v) {
        skip_blanks();
        std::size_t n = 0;
        while (n < s.size() && std::isdigit(static_cast<unsigned char>(s[n]))) ++n;
        if (n == 0 || n > 6) return false;
        v = std::atoi(std::string(s.substr(0, n)).c_str());
        s.remove_prefix(n);
        return true;
    }
    std::string word() {
        skip_blanks();
        std::size_t n = 0;
        while (n < s.size() && !std::isspace(static_cast<unsigned char>(s[n]))) ++n;
        std::string w(s.substr(0, n));
        s.remove_prefix(n);
        return w;
    }
    bool at_end() {
        skip_blanks();
        return s.empty();
    }
};

struct Version {
    bool core = false, compat = false, es = false;
    Comparison comparison = Comparison::GreaterEqual;
    int number = 0;  // 45 for GL 4.5, 450 for GLSL 4.50
};

// "[CORE|COMPAT|ES] >= 4.50"; false for a malformed one.
bool parse_version(Cursor& c, bool glsl, Version& v) {
    v.core = c.take("CORE");
    v.compat = c.take("COMPAT");
    v.es = c.take("ES");
    int major = 0, minor = 0;
    if (!c.comparison(v.comparison) || !c.unsigned_number(major) || !c.take(".") || !c.unsigned_number(minor)) return false;
    if (!c.at_end()) return false;
    v.number = glsl ? major * 100 + minor : major * 10 + minor;
    return true;
}

std::string version_text(const char* what, const Version& v, bool glsl) {
    const int major = glsl ? v.number / 100 : v.number / 10, minor = glsl ? v.number % 100 : v.number % 10;
    std::string minor_text = std::to_string(minor);
    if (glsl && minor < 10) minor_text = "0" + minor_text;
    return std::string(what) + (v.es ? " ES " : " ") + comparison_text(v.comparison) + " " + std::to_string(major) + "." +
           minor_text;
}

}  // namespace

const Implementation& Implementation::quadshade() {
    static const Implementation q = [] {
        Implementation i;
        // Only extensions whose every shading feature the front end runs: the fine and coarse
        // derivatives (under every rule), attribute locations, floatBitsToInt and the like.
        i.extensions = {"GL_ARB_derivative_control", "GL_ARB_explicit_attrib_location", "GL_ARB_shader_bit_encoding"};
        i.limits = {
            {"GL_MAX_VARYING_COMPONENTS", kMaxVaryings},
            {"GL_MAX_VERTEX_OUTPUT_COMPONENTS", kMaxVaryings},
            {"GL_MAX_FRAGMENT_UNIFORM_COMPONENTS", 65536},
            {"GL_MAX_VERTEX_UNIFORM_COMPONENTS", 65536},
            {"GL_MAX_VERTEX_ATTRIBS", kMaxGenericAttributes},
            {"GL_NUM_PROGRAM_BINARY_FORMATS", 0},
        };
        return i;
    }();
    return q;
}

bool Implementation::has_extension(const std::string& name) const {
    return std::find(extensions.begin(), extensions.end(), name) != extensions.end();
}

std::optional<int> Implementation::limit(const std::string& name) const {
    for (const auto& [n, v] : limits) {
        if (n == name) return v;
    }
    return std::nullopt;
}

namespace {

// A test's [require] lines read in order. The first line not met or malformed decides, as
// shader_runner stops at it.
class RequirementReader {
public:
    RequirementReader(const ShaderTest& test, const Implementation& impl) : test_(test), impl_(impl) {}

    Requirements read() {
        for (const Line& line : test_.require) read_line(line);
        return r_;
    }

private:
    void fail(const Line& line, const std::string& message) {
        if (!r_.error && !r_.unmet) r_.error = test_.file + ":" + std::to_string(line.number) + ": " + message;
    }
    void unmet(const std::string& reason) {
        if (!r_.error && !r_.unmet) r_.unmet = reason;
    }

    void read_line(const Line& line) {
        Cursor c{line.text};
        if (c.take("INT ")) return integer_limit(line, c);
        if (named_limit(line, c)) return;
        Cursor e = c;
        if (e.take("GL_")) {
            const std::string name = "GL_" + e.word();
            if (!impl_.has_extension(name)) unmet(name);
        } else if (e.take("!") && e.take("GL_")) {
            const std::string name = "GL_" + e.word();
            if (impl_.has_extension(name)) unmet("!" + name);
        } else if (c.take("GLSL")) {
            glsl_version(line, c);
        } else if (c.take("GL")) {
            gl_version(line, c);
        } else if (c.take("SIZE")) {
            window_size(line, c);
        } else if (c.take("depthbuffer")) {
            r_.depth_buffer = true;
        } else if (c.take("SSO") || c.take("SEPARABLE PROGRAM")) {
            unmet("separate shader objects");
        } else if (c.take("SPIRV")) {
            if (c.take("ONLY")) unmet("SPIR-V only");
        }
        // rlimit, and lines piglit does not know, change nothing.
    }

    // INT name cmp value: glGetIntegerv of any enum; quadshade answers only the limits it lists.
    void integer_limit(const Line& line, Cursor& c) {
        const std::string name = c.word();
        Comparison cmp;
        int value = 0;
        if (!c.comparison(cmp) || !c.unsigned_number(value)) {
            return fail(line, "invalid INT requirement '" + line.text + "'");
        }
        const std::optional<int> actual = impl_.limit(name);
        if (!actual) unmet(name + " (not answered)");
        else if (!compare(value, *actual, cmp)) unmet(name + " " + comparison_text(cmp) + " " + std::to_string(value));
    }

    // A line that starts with one of the limits quadshade lists (GL_MAX_...): false for others.
    bool named_limit(const Line& line, const Cursor& c) {
        for (const auto& [name, actual] : impl_.limits) {
            Cursor l = c;
            if (!l.take(name)) continue;
            Comparison cmp;
            if (!l.comparison(cmp)) {
                fail(line, "invalid comparison in '" + line.text + "'");
                return true;
            }
            l.skip_blanks();
            const int value = std::atoi(std::string(l.s).c_str());
            if (!compare(value, actual, cmp)) unmet(name + " " + comparison_text(cmp) + " " + std::to_string(value));
            return true;
        }
        return false;
    }

    // GLSL [ES] >= 4.50: only >= is accepted.
    void glsl_version(const Line& line, Cursor& c) {
        Version v;
        if (!parse_version(c, true, v)) return fail(line, "invalid GLSL version requirement '" + line.text + "'");
        if (v.comparison != Comparison::GreaterEqual) {
            return fail(line, "unsupported GLSL version comparison '" + line.text + "' (only >=)");
        }
        r_.glsl_version = v.number;
        r_.glsl_es = v.es;
        if (v.es || !compare(v.number, impl_.glsl_version, v.comparison)) unmet(version_text("GLSL", v, true));
    }

    // GL [CORE|COMPAT|ES] >= 4.5, or another comparison.
    void gl_version(const Line& line, Cursor& c) {
        Version v;
        if (!parse_version(c, false, v)) return fail(line, "invalid GL version requirement '" + line.text + "'");
        r_.gl_version = v.number;
        r_.gl_es = v.es;
        r_.gl_core = v.core;
        if (v.es || !compare(v.number, impl_.gl_version, v.comparison)) unmet(version_text("GL", v, false));
    }

    // SIZE width height: the window, 1..16384 each way.
    void window_size(const Line& line, Cursor& c) {
        int w = 0, h = 0;
        if (!c.unsigned_number(w) || !c.unsigned_number(h) || w < 1 || h < 1 || w > 16384 || h > 16384) {
            return fail(line, "invalid SIZE '" + line.text + "'");
        }
        r_.width = w, r_.height = h;
    }

    const ShaderTest& test_;
    const Implementation& impl_;
    Requirements r_;
};

}  // namespace

Requirements check_requirements(const ShaderTest& test, const Implementation& impl) {
    return RequirementReader(test, impl).read();
}

}  // namespace qs::piglit
