#include "frontend/program_interface.h"

namespace qs::frontend {

namespace {

const char* bank_name(ir::Bank b) {
    switch (b) {
        case ir::Bank::Float: return "float";
        case ir::Bank::Int: return "int";
        case ir::Bank::Uint: return "uint";
        case ir::Bank::Bool: return "bool";
    }
    return "?";
}

}  // namespace

int ProgramInterface::uniform(const ir::Uniform& u, const std::string& where, bool initialised) {
    for (std::size_t i = 0; i < program.uniforms.size(); ++i) {
        ir::Uniform& have = program.uniforms[i];
        if (have.name != u.name) continue;
        if (have.bank != u.bank || have.components != u.components || have.columns != u.columns) {
            throw GlslLinkError(where + "uniform '" + u.name + "' is declared with another type in the other stage");
        }
        // The program has one uniform of the name: an initializer in either stage is its own.
        if (initialised && uniform_initialised[i] && have.initial != u.initial) {
            throw GlslLinkError(where + "uniform '" + u.name + "' has another initializer in the other stage");
        }
        if (initialised && !uniform_initialised[i]) {
            have.initial = u.initial;
            uniform_initialised[i] = true;
        }
        return int(i);
    }
    program.uniforms.push_back(u);
    uniform_initialised.push_back(initialised);
    return int(program.uniforms.size() - 1);
}

int ProgramInterface::sampler(const std::string& name, int dims, bool shadow, const std::string& where) {
    for (std::size_t i = 0; i < program.samplers.size(); ++i) {
        if (program.samplers[i].name != name) continue;
        if (program.samplers[i].dims != dims || program.samplers[i].shadow != shadow) {
            throw GlslLinkError(where + "sampler '" + name + "' is declared with another type in the other stage");
        }
        return int(i);
    }
    program.samplers.push_back({name, dims, shadow});
    return int(program.samplers.size() - 1);
}

VaryingSlot& ProgramInterface::fragment_varying(const std::string& name, int components, ir::Bank bank, bool flat,
                                                const std::string& where, bool noperspective) {
    if (VaryingSlot* v = find_varying(name)) return *v;
    VaryingSlot v{name, int(program.varyings.size()), components, bank, flat, noperspective, where, false};
    for (int i = 0; i < components; ++i) {
        program.varyings.push_back({components == 1 ? name : name + "[" + std::to_string(i) + "]", flat, noperspective});
    }
    (void)bank_name;
    varyings.push_back(v);
    return varyings.back();
}

VaryingSlot* ProgramInterface::find_varying(const std::string& name) {
    for (VaryingSlot& v : varyings) {
        if (v.name == name) return &v;
    }
    return nullptr;
}

}  // namespace qs::frontend
