#include "scenes/uniforms.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace qs {

bool is_uniform_name(std::string_view name) {
    if (name.empty() || name.starts_with("gl_")) return false;
    auto letter = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
    if (!letter(name[0])) return false;
    for (char c : name) {
        if (!letter(c) && !(c >= '0' && c <= '9')) return false;
    }
    return true;
}

UniformSetting parse_uniform_option(std::string_view text) {
    const std::string shown = "--uniform " + std::string(text);
    const std::size_t eq = text.find('=');
    if (eq == std::string_view::npos) throw UniformOptionError(shown + ": expected NAME=VALUE");
    UniformSetting s;
    s.name = std::string(text.substr(0, eq));
    s.origin = shown;
    if (!is_uniform_name(s.name)) throw UniformOptionError(shown + ": '" + s.name + "' is not a uniform name");
    if (s.name == kResolutionUniform) {
        throw UniformOptionError(shown + ": " + std::string(kResolutionUniform) + " is the frame's size; use --size");
    }
    std::string_view list = text.substr(eq + 1);
    if (list.size() >= 2 && list.front() == '[' && list.back() == ']') list = list.substr(1, list.size() - 2);
    while (true) {
        const std::size_t comma = list.find(',');
        std::string_view item = list.substr(0, comma);
        while (!item.empty() && item.front() == ' ') item.remove_prefix(1);
        while (!item.empty() && item.back() == ' ') item.remove_suffix(1);
        double v = 0.0;
        const auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
        if (item.empty() || ec != std::errc() || end != item.data() + item.size() || !std::isfinite(v)) {
            throw UniformOptionError(shown + ": '" + std::string(item) + "' is not a finite number");
        }
        // A uniform is a float: 1e39 would become infinity there (and NaN on every pixel).
        if (std::abs(v) > double(std::numeric_limits<float>::max())) {
            throw UniformOptionError(shown + ": '" + std::string(item) + "' is beyond a float's range (3.4e38)");
        }
        s.values.push_back(v);
        if (comma == std::string_view::npos) break;
        list.remove_prefix(comma + 1);
    }
    if (s.values.size() > 16) throw UniformOptionError(shown + ": more than 16 numbers (a mat4 has 16)");
    return s;
}

std::vector<UniformSetting> merge_uniforms(const std::vector<UniformSetting>& material,
                                           const std::vector<UniformSetting>& command_line) {
    std::vector<UniformSetting> out = material;
    for (const UniformSetting& c : command_line) {
        bool replaced = false;
        for (UniformSetting& m : out) {
            if (m.name == c.name) m = c, replaced = true;
        }
        if (!replaced) out.push_back(c);
    }
    return out;
}

}  // namespace qs
