#pragma once
// The shader catalogue: every shader this process knows, built in or from a plugin, looked up by
// the name scenes use. Shaders register themselves where they are defined, one line after their
// structs (a family header of shading/shaders/, or a user's plugin):
//
//     QUADSHADE_SHADERS(Dots, Perlin)
//     QUADSHADE_SHADERS_IN("my textures", Stripes, Checks)  // in a collection
//
// A line registers its shaders once however many files include it, so a header may hold it; each
// file that includes it compiles the shaders' every instantiation, though, so a family header is
// included by the one file that builds it (shading/CMakeLists.txt generates it).
//
// A collection groups shaders for listings and the gallery (the built-in ones by the text they
// come from, shading/shaders/collections.h); a plugin's shaders outside one are grouped under the
// plugin's file name.
//
// Each shader's GLSL files (ShaderInfo::glsl_vertex / glsl_fragment) are found under its origin's
// GLSL folder: for the built-in shaders `share/quadshade/shading` beside the executable's `bin/`
// (the build tree has the same layout), for a plugin the plugin's own folder; a stock vertex
// stage's (ShaderInfo::stock_vertex_glsl) under the built-in shaders' folder.

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "shading/program.h"

namespace qs {

using ProgramList = std::vector<const Program*>;

// All programs: the built-in ones in the order their files are linked (Figure 1.1, Table 1.1,
// the other chapter patterns, probes, ...), then each plugin's in the order it was loaded.
const ProgramList& catalogue();
// nullptr when no shader has that name.
const Program* find_program(std::string_view name);
// The folder the GLSL file names of `program`'s fragment stage, or of its vertex stage, are
// relative to.
std::filesystem::path glsl_folder(const Program& program, bool vertex_stage = false);
// The plugin `program` came from; empty for a built-in shader.
const std::filesystem::path& plugin_of(const Program& program);
// The collection `program` was registered in (QUADSHADE_SHADERS_IN), else its plugin's file name,
// else "other".
std::string collection_of(const Program& program);
// The catalogue grouped by collection, collections in order of their names, each in catalogue
// order.
std::vector<std::pair<std::string, ProgramList>> catalogue_by_collection();

// A shader compiled while quadshade runs (a user's GLSL, interpreter/glsl_program.h): the
// catalogue keeps it, in `collection`, with the GLSL text of each stage as the reference is to
// compile it. Throws std::invalid_argument where its name is taken.
const Program& add_compiled_program(std::unique_ptr<Program> program, std::string collection, std::string vertex_glsl,
                                    std::string fragment_glsl);
// A compiled program's GLSL (vertex or fragment stage); nullptr for a translated one.
const std::string* compiled_glsl(const Program& program, bool vertex_stage);

// What crosses between quadshade and a plugin's shaders, as the plugin's headers laid it out: a
// plugin built against other headers is refused, not run.
struct ShaderAbi {
    int version = 4;  // raised when program.h's contract changes in a way sizes do not show
    int batch_lanes = kBatchLanes;
    int max_varyings = kMaxVaryings;
    std::size_t fragment_batch = sizeof(FragmentBatch);
    std::size_t color_batch = sizeof(ColorBatch);
    std::size_t uniforms = sizeof(Uniforms);
    std::size_t sampler2d = sizeof(glsl::sampler2D);
    std::size_t shader_info = sizeof(ShaderInfo);
    bool operator==(const ShaderAbi&) const = default;
};

namespace registration {

// Adds `program` to the catalogue, in `collection` (empty: none), from the plugin being loaded if
// any (render/plugins.h). A name already taken, or an `abi` other than this build's, is recorded
// and reported by the loader (or, for a built-in shader, by the first call to catalogue()).
// `optimised`: whether the code that registers it was compiled with optimisation (a plugin built
// without renders several times slower, and the loader warns).
void add(const Program& program, const ShaderAbi& abi, std::string_view collection, bool optimised = true);

// Where registrations come from while a plugin's static constructors run; empty when built in.
void begin_plugin(const std::filesystem::path& plugin);
// The problems recorded since begin_plugin, and how many shaders it added; ends the plugin.
struct PluginResult {
    int added = 0;
    std::vector<std::string> problems;
    bool unoptimised = false;  // some of its shaders were compiled without optimisation
};
PluginResult end_plugin();

// One object per registration line: its constructor registers a ProgramOf<S> for each S.
template <class... Shaders>
struct Registrar {
    explicit Registrar(std::string_view collection) { (add(program<Shaders>(), ShaderAbi{}, collection, kOptimised), ...); }
#if defined(__OPTIMIZE__)
    static constexpr bool kOptimised = true;  // as the file that registers them was compiled
#else
    static constexpr bool kOptimised = false;
#endif
    template <class S>
    static const Program& program();  // defined by program_of.h
};

// A collection's name as a template argument: a string literal or a constexpr string_view.
struct CollectionName {
    char text[128] = {};
    consteval CollectionName(std::string_view name) {  // NOLINT: the macro's argument, converted
        if (name.size() >= sizeof text) throw "a collection's name has at most 127 characters";
        for (std::size_t i = 0; i < name.size(); ++i) text[i] = name[i];
    }
    constexpr std::string_view view() const { return text; }
};

// The registration of `Shaders` in collection C: one object in the program, however many files
// name it (an inline variable).
template <CollectionName C, class... Shaders>
inline const Registrar<Shaders...> registered{C.view()};

}  // namespace registration
}  // namespace qs

// Registers the shader structs it names (see program_of.h for what a shader struct holds), at
// namespace scope in a file that includes shading/program_of.h; _IN puts them in a collection.
#define QUADSHADE_SHADERS_IN(collection, ...)                                                         \
    namespace {                                                                                        \
    [[maybe_unused]] const auto& QUADSHADE_REGISTRAR_NAME(__COUNTER__) =                               \
        ::qs::registration::registered<::qs::registration::CollectionName{collection}, __VA_ARGS__>;  \
    }
#define QUADSHADE_SHADERS(...) QUADSHADE_SHADERS_IN("", __VA_ARGS__)
#define QUADSHADE_REGISTRAR_NAME(n) QUADSHADE_REGISTRAR_NAME_(n)
#define QUADSHADE_REGISTRAR_NAME_(n) quadshade_registered_shaders_##n
