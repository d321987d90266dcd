// A glTF material that names GLSL files (extras.glsl) is drawn by them, as --glsl draws them on
// every object; the files are the scene's inputs, confined to its folder like its textures.

#include <catch2/catch.hpp>

#include <fstream>

#include <nlohmann/json.hpp>

#include "render/glsl_shaders.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "tests/test_paths.h"

namespace {

using namespace qs;

const char* kRings = R"(#version 120
varying vec2 st;
void main() {
    float r = length(st - 0.5);
    gl_FragColor = vec4(vec3(0.5 + 0.5 * sin(r * 60.0)), 1.0);
}
)";

// The Table 1.1 plane saved into `dir` with its material drawn by `glsl` (a file name in dir).
std::filesystem::path plane_with_glsl(const std::filesystem::path& dir, const std::string& glsl) {
    Scene s = load_scene(test::kPlane);
    test::copy_textures_into(s, dir);
    s.objects[0].shader.clear();
    s.objects[0].glsl_fragment = dir / glsl;
    const auto file = dir / "plane.gltf";
    save_scene(s, file);
    return file;
}

}  // namespace

TEST_CASE("a material that names a GLSL file is drawn by it, as --glsl draws it", "[interpreter][gltf]") {
    const auto dir = test::temp_dir("glsl-material");
    std::ofstream(dir / "rings.frag") << kRings;
    Scene scene = load_scene(plane_with_glsl(dir, "rings.frag"));
    REQUIRE(scene.objects[0].glsl_fragment == std::filesystem::weakly_canonical(dir / "rings.frag"));
    CHECK(std::find(scene.inputs.begin(), scene.inputs.end(), scene.objects[0].glsl_fragment) != scene.inputs.end());

    FrameRequest r;
    r.width = r.height = 32;
    const Framebuffer by_material = render_frame(scene, r);
    r.shader_override = std::string(load_glsl_shader(dir / "rings.frag", std::nullopt).program->info().name);
    const Framebuffer by_option = render_frame(scene, r);
    CHECK(by_material.rgba == by_option.rgba);
    float lowest = 1.0f, highest = 0.0f;
    for (std::size_t i = 0; i < by_material.rgba.size(); i += 4) {
        lowest = std::min(lowest, by_material.rgba[i]), highest = std::max(highest, by_material.rgba[i]);
    }
    CHECK(highest - lowest > 0.5f);  // the rings, not the default material's flat colour
}

TEST_CASE("a material's GLSL files: outside the scene's folder, beside a shader, or not GLSL, are refused by field", "[interpreter][gltf]") {
    const auto dir = test::temp_dir("glsl-material-refused");
    std::filesystem::create_directories(dir / "scene");
    std::ofstream(dir / "outside.frag") << kRings;
    std::ofstream(dir / "scene" / "broken.frag") << "#version 120\nvoid main() { gl_FragColor = vec4(1.0) +; }\n";
    auto message = [](const std::filesystem::path& file) -> std::string {
        try {
            Scene s = load_scene(file);
            FrameRequest r;
            r.width = r.height = 8;
            (void)render_frame(s, r);
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    };
    // Edited as JSON: save_scene writes only what a loaded scene can hold.
    auto scene_naming = [&](const std::string& extras) {
        Scene s = load_scene(test::kPlane);
        test::copy_textures_into(s, dir / "scene");
        save_scene(s, dir / "scene" / "plane.gltf");
        std::ifstream in(dir / "scene" / "plane.gltf");
        nlohmann::json gltf = nlohmann::json::parse(in);
        gltf["materials"][0]["extras"] = nlohmann::json::parse(extras);
        std::ofstream(dir / "scene" / "plane.gltf") << gltf.dump();
        return dir / "scene" / "plane.gltf";
    };
    const std::string outside = message(scene_naming(R"({"glsl": "../outside.frag"})"));
    INFO(outside);
    CHECK(outside.find("extras.glsl") != std::string::npos);
    const std::string both = message(scene_naming(R"({"glsl": "broken.frag", "shader": "dots"})"));
    INFO(both);
    CHECK(both.find("give one of them") != std::string::npos);
    const std::string broken = message(scene_naming(R"({"glsl": {"fragment": "broken.frag"}})"));
    INFO(broken);
    CHECK(broken.find("extras.glsl: ") != std::string::npos);
    CHECK(broken.find("broken.frag:2: error: ") != std::string::npos);
}
