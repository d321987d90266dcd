#pragma once
// Values for shaders' own uniforms, as a scene (a material's extras.uniforms) or a command line
// (--uniform name=value) gives them. Only the numbers and where they come from: which uniform of
// which type they meet is each renderer's business (quadshade's from the shader's declarations,
// the reference's from GL's list of the program's uniforms).

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace qs {

// A --uniform the command line cannot have: bad usage (exit 2), where a scene's is bad input.
class UniformOptionError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

struct UniformSetting {
    std::string name;
    // 1 number (float, int, uint), 2 to 4 (vectors), 4, 9 or 16 (mat2, mat3, mat4, column by
    // column, as GLSL's constructors and glUniformMatrix take them). All finite.
    std::vector<double> values;
    // Where it was given, for messages: "scene.gltf: materials[0].extras.uniforms.uScale" or
    // "--uniform uScale=4".
    std::string origin;
};

// A command line's `--uniform` argument: NAME=V or NAME=V,V,... (brackets around the list
// allowed: NAME=[1,0.5,0.2]). Throws UniformOptionError saying what is wrong.
UniformSetting parse_uniform_option(std::string_view text);

// The settings that apply to one object: its material's, each replaced by a command line's of
// the same name; then the command line's the material does not name.
std::vector<UniformSetting> merge_uniforms(const std::vector<UniformSetting>& material,
                                           const std::vector<UniformSetting>& command_line);

// Whether `name` is a GLSL identifier (and not a reserved gl_ one).
bool is_uniform_name(std::string_view name);

// The uniform both renderers set themselves: the frame's size in pixels (vec2), as Shadertoy's
// iResolution. A scene or command line may not set it.
inline constexpr std::string_view kResolutionUniform = "uResolution";

}  // namespace qs
