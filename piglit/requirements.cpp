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

Requirements check_requirements(const ShaderTest& test, const Implementation& impl) {
    Requirements r;
    // The first line not met or malformed decides, as shader_runner stops at it.
    const auto fail = [&](const Line& line, const std::string& message) {
        if (!r.error && !r.unmet) r.error = test.file + ":" + std::to_string(line.number) + ": " + message;
    };
    const auto unmet = [&](const std::string& reason) {
        if (!r.error && !r.unmet) r.unmet = reason;
    };
    for (const Line& line : test.require) {
        Cursor c{line.text};
        if (c.take("INT ")) {
            // glGetIntegerv of any enum: quadshade answers only the limits it lists.
            const std::string name = c.word();
            Comparison cmp;
            int value = 0;
            if (!c.comparison(cmp) || !c.unsigned_number(value)) {
                fail(line, "invalid INT requirement '" + line.text + "'");
                continue;
            }
            const std::optional<int> actual = impl.limit(name);
            if (!actual) unmet(name + " (not answered)");
            else if (!compare(value, *actual, cmp)) unmet(name + " " + comparison_text(cmp) + " " + std::to_string(value));
            continue;
        }
        bool limit_line = false;
        for (const auto& [name, actual] : impl.limits) {
            Cursor l = c;
            if (!l.take(name)) continue;
            limit_line = true;
            Comparison cmp;
            if (!l.comparison(cmp)) {
                fail(line, "invalid comparison in '" + line.text + "'");
                break;
            }
            l.skip_blanks();
            const int value = std::atoi(std::string(l.s).c_str());
            if (!compare(value, actual, cmp)) unmet(name + " " + comparison_text(cmp) + " " + std::to_string(value));
            break;
        }
        if (limit_line) continue;
        Cursor e = c;
        if (e.take("GL_")) {
            const std::string name = "GL_" + e.word();
            if (!impl.has_extension(name)) unmet(name);
        } else if (e.take("!") && e.take("GL_")) {
            const std::string name = "GL_" + e.word();
            if (impl.has_extension(name)) unmet("!" + name);
        } else if (c.take("GLSL")) {
            Version v;
            if (!parse_version(c, true, v)) {
                fail(line, "invalid GLSL version requirement '" + line.text + "'");
                continue;
            }
            if (v.comparison != Comparison::GreaterEqual) {
                fail(line, "unsupported GLSL version comparison '" + line.text + "' (only >=)");
                continue;
            }
            r.glsl_version = v.number;
            r.glsl_es = v.es;
            if (v.es || !compare(v.number, impl.glsl_version, v.comparison)) unmet(version_text("GLSL", v, true));
        } else if (c.take("GL")) {
            Version v;
            if (!parse_version(c, false, v)) {
                fail(line, "invalid GL version requirement '" + line.text + "'");
                continue;
            }
            r.gl_version = v.number;
            r.gl_es = v.es;
            r.gl_core = v.core;
            if (v.es || !compare(v.number, impl.gl_version, v.comparison)) unmet(version_text("GL", v, false));
        } else if (c.take("SIZE")) {
            int w = 0, h = 0;
            if (!c.unsigned_number(w) || !c.unsigned_number(h) || w < 1 || h < 1 || w > 16384 || h > 16384) {
                fail(line, "invalid SIZE '" + line.text + "'");
                continue;
            }
            r.width = w, r.height = h;
        } else if (c.take("depthbuffer")) {
            r.depth_buffer = true;
        } else if (c.take("SSO") || c.take("SEPARABLE PROGRAM")) {
            unmet("separate shader objects");
        } else if (c.take("SPIRV")) {
            if (c.take("ONLY")) unmet("SPIR-V only");
        }
        // rlimit, and lines piglit does not know, change nothing.
    }
    return r;
}

}  // namespace qs::piglit
