#include "render/uniform_binding.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string_view>

#include "scenes/scene.h"
#include "scenes/shader_inputs.h"

namespace qs {

namespace {

[[noreturn]] void refuse(const UniformSetting& s, const std::string& what) {
    const std::string message = s.origin + ": " + what;
    if (s.origin.starts_with("--uniform")) throw UniformOptionError(message);
    throw SceneError(message);
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", v);
    return text;
}

std::string declared_list(const ShaderInfo& info) {
    std::string names;
    for (const UniformDecl& d : info.uniforms) {
        if (d.name == kResolutionUniform) continue;
        names += (names.empty() ? "" : ", ") + std::string(glsl_name(d.type)) + " " + std::string(d.name);
    }
    return names.empty() ? "none" : names;
}

}  // namespace

bool declares_uniform(const ShaderInfo& info, const std::string& name) {
    for (const UniformDecl& d : info.uniforms) {
        if (d.name == name) return true;
    }
    return false;
}

std::vector<std::uint32_t> bind_uniforms(const ShaderInfo& info, const std::vector<UniformSetting>& settings, int width,
                                         int height, bool ignore_unknown_material) {
    std::vector<std::uint32_t> words(info.uniforms.size() * kUniformWords, 0u);
    std::vector<bool> set(info.uniforms.size(), false);
    for (std::size_t u = 0; u < info.uniforms.size(); ++u) {
        const UniformDecl& d = info.uniforms[u];
        if (find_scene_matrix(d.name)) {
            throw std::logic_error("shader '" + std::string(info.name) + "' declares uniform '" + std::string(d.name) +
                                   "', which is the scene's transform: read it from Uniforms (u.model_view_projection, "
                                   "u.model, u.view, u.projection, u.normal_matrix), not from ShaderInfo::uniforms");
        }
        std::uint32_t* w = &words[u * kUniformWords];
        for (int i = 0; i < components(d.type); ++i) w[i] = uniform_word(d.type, double(d.initial[std::size_t(i)]));
        if (d.name == kResolutionUniform) {
            w[0] = uniform_word(d.type, double(width));
            w[1] = uniform_word(d.type, double(height));
        }
    }
    for (const UniformSetting& s : settings) {
        const std::string shader(info.name);
        if (s.name == kResolutionUniform) refuse(s, std::string(kResolutionUniform) + " is the frame's size, set by the renderer");
        if (find_scene_matrix(s.name)) refuse(s, s.name + " is the scene's transform, set by the renderer");
        std::size_t u = 0;
        while (u < info.uniforms.size() && info.uniforms[u].name != s.name) ++u;
        if (u == info.uniforms.size()) {
            // A command line's may be for another drawn shader: the caller checks that one declares it.
            if (s.origin.starts_with("--uniform") || ignore_unknown_material) continue;
            refuse(s, "shader '" + shader + "' declares no uniform '" + s.name + "' (it declares: " + declared_list(info) + ")");
        }
        const UniformDecl& d = info.uniforms[u];
        const std::string type(glsl_name(d.type));
        if (int(s.values.size()) != components(d.type)) {
            refuse(s, "uniform '" + s.name + "' of shader '" + shader + "' is " + type + ": expected " +
                          std::to_string(components(d.type)) + " number(s), got " + std::to_string(s.values.size()));
        }
        for (std::size_t i = 0; i < s.values.size(); ++i) {
            const double v = s.values[i];
            if (!std::isfinite(v)) refuse(s, "uniform '" + s.name + "': not a finite number");
            if (is_integer(d.type)) {
                const bool is_uint = is_unsigned(d.type);
                const double lo = is_uint ? 0.0 : -2147483648.0, hi = is_uint ? 4294967295.0 : 2147483647.0;
                if (v != std::trunc(v) || v < lo || v > hi) {
                    refuse(s, "uniform '" + s.name + "' of shader '" + shader + "' is " + type + ": " +
                                  number(v) + " is not one (an integer in [" + std::to_string(std::int64_t(lo)) + ", " +
                                  std::to_string(std::int64_t(hi)) + "])");
                }
            }
            words[u * kUniformWords + i] = uniform_word(d.type, v);
        }
        set[u] = true;
    }
    // A matrix nothing sets is all zeros: never a transform a shader means, and what a vertex
    // stage reading a transform under a name the scene does not feed would get. Refused, as the
    // reference refuses it.
    for (std::size_t u = 0; u < info.uniforms.size(); ++u) {
        const UniformDecl& d = info.uniforms[u];
        if (set[u] || d.type < UniformType::Mat2) continue;
        bool zero = true;
        for (int i = 0; i < components(d.type); ++i) zero = zero && d.initial[std::size_t(i)] == 0.0f;
        if (zero) {
            throw SceneError("shader '" + std::string(info.name) + "': uniform " + std::string(glsl_name(d.type)) + " '" +
                             std::string(d.name) + "' is none of the scene's transforms (" + std::string(scene_matrix_names()) +
                             ") and nothing sets it (no initializer, material extras.uniforms or --uniform): it would be "
                             "all zeros");
        }
    }
    return words;
}

}  // namespace qs
