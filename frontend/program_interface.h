#pragma once
// What the two stages of a program share while they are lowered: the uniforms and samplers,
// named once for both stages, and the varyings, which the fragment stage's reads define and
// the vertex stage's writes must supply (GL's linking of the interface, by name).

#include <string>
#include <vector>

#include "frontend/compile_options.h"
#include "frontend/glsl_error.h"
#include "frontend/ir.h"

namespace qs::frontend {

// One varying of the fragment stage: its floats are Source::Varying first..first+components-1.
struct VaryingSlot {
    std::string name;      // GLSL name; gl_TexCoord[i] and gl_Color as those names
    int first = 0;
    int components = 0;
    ir::Bank bank = ir::Bank::Float;  // int and uint varyings travel as their bits (flat)
    bool flat = false;
    bool noperspective = false;
    std::string where;     // FILE:LINE:COL of the fragment stage's declaration, for messages
    bool written = false;  // the vertex stage writes it
};

struct ProgramInterface {
    ir::Program& program;
    std::vector<VaryingSlot> varyings;
    CompileOptions options;
    std::vector<bool> uniform_initialised;  // per slot of program.uniforms: declared with an initializer
    int probe_components = 0;               // the derivative probe's expression's components, once lowered

    // The slot of the user uniform `u`, added on first use; a second declaration must agree,
    // in its type and, where both have one, in its initializer (u.initial, when `initialised`).
    int uniform(const ir::Uniform& u, const std::string& where, bool initialised);
    // The slot of the sampler `name` (`shadow`: a sampler2DShadow).
    int sampler(const std::string& name, int dims, bool shadow, const std::string& where);
    // The fragment stage's varying `name`, added on first use.
    VaryingSlot& fragment_varying(const std::string& name, int components, ir::Bank bank, bool flat,
                                  const std::string& where, bool noperspective = false);
    // The fragment stage's varying the vertex stage's output `name` feeds, or nullptr.
    VaryingSlot* find_varying(const std::string& name);
};

}  // namespace qs::frontend
