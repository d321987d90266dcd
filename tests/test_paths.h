#pragma once
// Where tests find the sources, the built programs and a scratch folder of their own.

#include <unistd.h>

#include <filesystem>
#include <set>
#include <string>
#include <string_view>

#include "scenes/gltf.h"
#include "scenes/scene.h"
#include "shading/shader_info.h"

namespace qs::test {

inline const std::filesystem::path kSource = QUADSHADE_SOURCE_DIR;
inline const std::filesystem::path kBin = QUADSHADE_BIN_DIR;
inline const std::filesystem::path kFigure = kSource / "scenes/assets/figure-1.1.gltf";
// The chapter's sphere alone, in perspective: where solid textures are compared.
inline const std::filesystem::path kSphere = kSource / "scenes/assets/sphere.gltf";
inline const std::filesystem::path kPlane = kSource / "scenes/assets/table-1.1-plane.gltf";
// The ProcTexGen articles' solid textures on Figure 1.1's spheres, fast_noise reading the shipped volume.
inline const std::filesystem::path kProcTexGenSpheres = kSource / "scenes/assets/proctexgen-spheres.gltf";
// The Table 1.1 plane binding the two textures Lawlor's snippets read (tex1, tex4).
inline const std::filesystem::path kLawlorPlane = kSource / "scenes/assets/lawlor-plane.gltf";

// The plane a shader of the plane is shown on: its source text's where the text reads textures of its own.
inline const std::filesystem::path& plane_for(std::string_view shader) {
    return shader.starts_with("lawlor_") ? kLawlorPlane : kPlane;
}

// Whether that plane binds every named sampler the shader declares (baked_lit's `normalmap` is
// bound only by the baked scenes it draws, where tests/reference/test_atlas_bake.cpp compares it).
inline bool plane_binds_samplers(const ShaderInfo& info) {
    const Scene plane = load_scene(plane_for(info.name));
    for (const SamplerUse& s : info.needs.samplers) {
        if (!s.name.empty() && plane.objects.at(0).texture_for(s.name) < 0) return false;
    }
    return true;
}

// Translations written in the order Mesa's optimiser reassociates a sum to rather than as their
// GLSL reads (each one's comment says which sum), so that they match llvmpipe: their GLSL run as
// written by the interpreter rounds as written, an ulp away, which a hash or an escape time turns
// into whole steps.
inline const std::set<std::string, std::less<>> kReassociatedByMesa = {"hash_hoskins", "lawlor_mandelbrot"};

// A fresh, empty folder under the system's temporary directory, unique to this process.
inline std::filesystem::path temp_dir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("quadshade-test-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

// The scene's texture files copied to `dir`/textures and named from there, for a scene to be
// saved into `dir`: a scene may read only files in its own folder (scenes/scene_files.h).
inline void copy_textures_into(Scene& scene, const std::filesystem::path& dir) {
    std::filesystem::create_directories(dir / "textures");
    for (Texture& t : scene.textures) {
        if (t.image.kind != ImageSource::Kind::File || !std::filesystem::exists(t.image.file)) continue;
        const auto copy = dir / "textures" / t.image.file.filename();
        std::filesystem::copy_file(t.image.file, copy, std::filesystem::copy_options::overwrite_existing);
        t.image.file = copy;
    }
}

}  // namespace qs::test
