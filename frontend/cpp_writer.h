#pragma once
// GLSL to C++: a vertex and fragment shader pair written as the translation a person would write
// by hand (shading/shaders/), from glslang's syntax tree: GLSL's names, one C++ statement per
// GLSL statement with its line, the vocabulary of shading/glsl/ over the number type F, and the
// ShaderInfo the front end derives from the source. What the front end refuses is refused here
// too, with the same message; constructs the writer has no readable C++ for are refused with
// FILE:LINE:COL and why (the shader still runs in the interpreter).
//
// No text of the GLSL reaches the C++ except identifiers, which are checked to be GLSL
// identifiers and renamed where C++ or quadshade gives their name another meaning, and numbers,
// which are written from their values. File names appear in comments only, with every character
// that could end a comment or a line replaced.

#include <optional>
#include <string>

#include "frontend/compile.h"

namespace qs::frontend {

struct Translation {
    std::string name;         // the shader's name and the C++ files' stem: a C identifier
    std::string header;       // <name>.h: the shader struct
    std::string source;       // <name>.cpp: its registration as a plugin
    std::string cmake;        // CMakeLists.txt: the plugin built against the installed package
    std::string struct_name;  // the shader struct's name, in namespace `name`
    // <name>.vert and <name>.frag: the vertex shader given (or the one quadshade wrote) and the
    // fragment shader, their #version lines blank (ShaderInfo::glsl_version writes it)
    std::string vertex_glsl;
    std::string fragment_glsl;
    // FILE:LINE:COL and why, where a loop may go round as often as llvmpipe's limit (65,535 times,
    // frontend/loop_bound.h), which llvmpipe and the interpreter keep and a C++ loop does not;
    // empty where every loop is bounded below it
    std::string unbounded_loop;
};

// The translation of `fragment` (with `vertex`, or the vertex shader quadshade writes for it),
// registered under `name` (a C identifier). Throws GlslError as compile_glsl does, and for what
// the writer does not translate.
// `shader_name`, where given, is the name the shader registers under (ShaderInfo::name) instead.
Translation translate_glsl(const GlslSource& fragment, const std::optional<GlslSource>& vertex, const std::string& name,
                           const std::string& shader_name = {});

// `text` made safe inside a C++ // comment: no line break, no character outside printable ASCII.
std::string comment_text(const std::string& text);

}  // namespace qs::frontend
