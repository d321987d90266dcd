// Fuzz target: the glTF scene loader on hostile files (JSON and binary glTF, told apart by the
// binary magic), the buffers they name beside them, their accessors and sparse data, the node
// tree, cameras, and the textures they name (decoded as a render would). Refusing input with a
// SceneError or ImageError is the expected way out; anything else (a crash, a sanitizer report,
// another exception such as std::bad_alloc, a loaded scene that breaks an invariant) is a bug.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "fuzz/fuzz_check.h"
#include "scenes/gltf.h"
#include "scenes/gltf_checks.h"
#include "scenes/texture_files.h"

namespace {

namespace fs = std::filesystem;

// A scene folder holding the files the shipped scenes name, so that the corpus's URIs resolve.
const fs::path& scene_folder() {
    static const fs::path dir = [] {
        const fs::path d = fs::temp_directory_path() / ("quadshade-fuzz-gltf-" + std::to_string(::getpid()));
        const fs::path assets = fs::path(QUADSHADE_SOURCE_DIR) / "scenes/assets";
        fs::create_directories(d / "textures");
        for (const char* f : {"figure-1.1.bin", "table-1.1-plane.bin", "textures/halftone-source.png"}) {
            fs::copy_file(assets / f, d / f, fs::copy_options::overwrite_existing);
        }
        std::atexit([] { std::error_code ec; fs::remove_all(scene_folder(), ec); });
        return d;
    }();
    return dir;
}

// What a loaded scene promises the renderer.
void check_scene(const qs::Scene& s) {
    FUZZ_CHECK(!s.objects.empty());
    for (const qs::Mesh& m : s.meshes) {
        FUZZ_CHECK(m.indices.size() % 3 == 0);
        for (std::uint32_t i : m.indices) FUZZ_CHECK(i < m.vertices.size());
        for (const qs::Vertex& v : m.vertices) {
            FUZZ_CHECK(std::isfinite(v.position.x) && std::isfinite(v.position.y) && std::isfinite(v.position.z));
            FUZZ_CHECK(std::isfinite(v.texcoord.x) && std::isfinite(v.texcoord.y));
        }
    }
    for (const qs::Object& o : s.objects) {
        FUZZ_CHECK(o.mesh < s.meshes.size());
        FUZZ_CHECK(o.texture < int(s.textures.size()));
        FUZZ_CHECK(qs::gltf_checks::places_things(o.world_from_object));
    }
    FUZZ_CHECK(qs::gltf_checks::is_finite(s.camera.projection(1.0f) * s.camera.view));
    FUZZ_CHECK(s.width >= 1 && s.height >= 1 && s.width <= 32768 && s.height <= 32768);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        qs::Scene scene = qs::parse_scene({data, size}, scene_folder() / "fuzz.gltf");
        check_scene(scene);
        for (const qs::Texture& t : scene.textures) {  // files, data: URIs and bufferViews
            try {
                const qs::Image8 image = qs::read_texture_image(t.image);
                FUZZ_CHECK(image.rgba.size() == std::size_t(image.width) * std::size_t(image.height) * 4);
            } catch (const qs::ImageError&) {
            }
        }
    } catch (const qs::SceneError&) {
    }
    return 0;
}
