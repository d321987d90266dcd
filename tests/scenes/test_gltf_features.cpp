// The glTF features exporters write, as the scene model reads them: primitive modes, normalized
// and quantized attributes, animations, instancing, cameras, extensions, the default material's
// data, transforms in double, and the messages (problems together, warnings counted). The
// feature scenes are generators/gltf_scenes.cpp's; their pixels are compared with OSMesa in
// tests/reference/test_gltf_scenes.cpp.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "render/scene_render.h"
#include "scenes/base64.h"
#include "scenes/gltf.h"
#include "scenes/object_uniforms.h"
#include "tests/test_command.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;
using json = nlohmann::json;

const std::filesystem::path kGltf = kSource / "scenes/assets/gltf";

// A file of one triangle (positions as floats) in a data: URI buffer, `extra` bytes after them
// for accessors of the test's own (their bufferViews start at byte 36).
json triangle_file(const std::vector<unsigned char>& extra = {}) {
    const float p[9] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};
    std::vector<unsigned char> bytes(36);
    std::memcpy(bytes.data(), p, 36);
    bytes.insert(bytes.end(), extra.begin(), extra.end());
    return json{{"asset", {{"version", "2.0"}}},
                {"scene", 0},
                {"scenes", {{{"nodes", {0}}}}},
                {"nodes", {{{"mesh", 0}}}},
                {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}}}}}}},
                {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}}}},
                {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
                {"buffers",
                 {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + base64(bytes)}}}}};
}

void write(const std::filesystem::path& file, const json& doc) { std::ofstream(file) << doc.dump(1); }

}  // namespace

TEST_CASE("glTF: triangle strips and fans are unrolled as GL draws them, points and lines skipped, counted once",
          "[scenes][gltf]") {
    const Scene s = load_scene(kGltf / "primitive-modes.gltf");
    // The strip, the fan and the box; the points, the lines and the line loop are skipped.
    REQUIRE(s.meshes.size() == 3);
    const std::vector<std::uint32_t>& strip = s.meshes[0].indices;
    REQUIRE(strip.size() == 3 * 32);  // 34 vertices: 32 triangles
    CHECK(std::vector<std::uint32_t>(strip.begin(), strip.begin() + 9) ==
          std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3, 2, 3, 4});
    const std::vector<std::uint32_t>& fan = s.meshes[1].indices;
    REQUIRE(fan.size() == 3 * 12);  // 14 vertices, not indexed: 12 triangles around vertex 0
    CHECK(std::vector<std::uint32_t>(fan.begin(), fan.begin() + 6) == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
    REQUIRE(s.warnings.size() == 1);
    CHECK(s.warnings[0].find("points and lines are not drawn: skipped 3 primitives of 2 meshes; first: "
                             "meshes[0].primitives[2] (mode 0)") != std::string::npos);
}

TEST_CASE("glTF: normalized and quantized attributes convert as glTF defines", "[scenes][gltf]") {
    const auto dir = temp_dir("gltf-normalized");
    // TEXCOORD_0 as normalized bytes (-128, 127, 0, 64, -1, 1), COLOR_0 as normalized unsigned
    // bytes (VEC3), NORMAL as normalized shorts.
    const std::vector<unsigned char> extra = {0x80, 0x7F, 0x00, 0x40, 0xFF, 0x01, 0,   0,  // 8 bytes of texcoords
                                              255,  0,    51,   0,    255,  102,  127, 1,
                                              0,    0,    0,    0,                 // 9 bytes of colours, padded
                                              0xFF, 0x7F, 0x00, 0x80, 0x00, 0x00,  // 32767, -32768, 0
                                              0x01, 0x00, 0x01, 0x80, 0x00, 0x00,  // 1, -32767, 0
                                              0x00, 0x00, 0x00, 0x00, 0xFF, 0x7F, 0,   0};  // 0, 0, 32767; padded
    json doc = triangle_file(extra);
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}});
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 9}});
    doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 56}, {"byteLength", 18}});
    doc["accessors"].push_back(
        {{"bufferView", 1}, {"componentType", 5120}, {"normalized", true}, {"count", 3}, {"type", "VEC2"}});
    doc["accessors"].push_back(
        {{"bufferView", 2}, {"componentType", 5121}, {"normalized", true}, {"count", 3}, {"type", "VEC3"}});
    doc["accessors"].push_back(
        {{"bufferView", 3}, {"componentType", 5122}, {"normalized", true}, {"count", 3}, {"type", "VEC3"}});
    doc["meshes"][0]["primitives"][0]["attributes"] = {
        {"POSITION", 0}, {"TEXCOORD_0", 1}, {"COLOR_0", 2}, {"NORMAL", 3}};
    write(dir / "n.gltf", doc);
    const Scene s = load_scene(dir / "n.gltf");
    const std::vector<Vertex>& v = s.meshes[0].vertices;
    CHECK(v[0].texcoord == glm::vec2(-1.0f, 1.0f));  // -128 clamps to -1, 127 is 1
    CHECK(v[1].texcoord == glm::vec2(0.0f, float(64.0 / 127.0)));
    CHECK(v[2].texcoord == glm::vec2(float(-1.0 / 127.0), float(1.0 / 127.0)));
    CHECK(v[0].color == glm::vec4(1.0f, 0.0f, 0.2f, 1.0f));  // 51 / 255 = 0.2; a VEC3 colour's alpha is 1
    CHECK(v[1].color == glm::vec4(0.0f, 1.0f, 0.4f, 1.0f));
    CHECK(v[0].normal == glm::vec3(1.0f, -1.0f, 0.0f));  // 32767, -32768 (clamped), 0
    CHECK(v[1].normal == glm::vec3(float(1.0 / 32767.0), -1.0f, 0.0f));
    CHECK(v[2].normal == glm::vec3(0.0f, 0.0f, 1.0f));
    CHECK(s.meshes[0].has_normals);

    // KHR_mesh_quantization: a sphere of shorts scaled back by its node.
    const Scene q = load_scene(kGltf / "quantized.gltf");
    const Mesh& sphere = q.meshes[0];
    CHECK(sphere.upper.x == 1000.0f);
    CHECK(q.objects[0].world_from_object[0][0] == Approx(0.001 * std::cos(glm::radians(20.0))).epsilon(1e-6));
    for (const Vertex& x : sphere.vertices) {
        CHECK(glm::length(x.normal) == Approx(1.0).margin(0.02));  // bytes: 1/127 a step
        CHECK(x.texcoord.x >= 0.0f);
        CHECK(x.texcoord.x <= 1.0f);
    }

    // A component type glTF does not allow for an attribute is refused, naming it.
    doc["accessors"][2]["componentType"] = 5120;  // COLOR_0 as signed bytes
    write(dir / "bad.gltf", doc);
    CHECK_THROWS_WITH(load_scene(dir / "bad.gltf"),
                      Catch::Contains("attributes.COLOR_0") && Catch::Contains("BYTE normalized"));
}

TEST_CASE("glTF: animations are posed as glTF interpolates (LINEAR, STEP, CUBICSPLINE, slerp), the camera too",
          "[scenes][gltf][animation]") {
    const Scene s = load_scene(kGltf / "animation.gltf");
    REQUIRE(s.animated());
    auto at = [&](double t, const std::string& name) {
        const Pose p = s.pose(t);
        for (std::size_t i = 0; i < s.objects.size(); ++i) {
            if (s.objects[i].name == name) return p.world_from_object[i];
        }
        FAIL("no object " << name);
        return glm::dmat4(1.0);
    };
    // LINEAR: (-2, 1, 0) at 0, (-2, -0.3, 0.5) at 1.
    const glm::dvec3 slider = glm::dvec3(at(0.25, "Slider")[3]);
    CHECK(slider.y == Approx(1.0 - 0.25 * 1.3));
    CHECK(slider.z == Approx(0.125));
    // Before the first keyframe the first value, after the last the last.
    CHECK(glm::dvec3(at(-1.0, "Slider")[3]).y == Approx(1.0));
    CHECK(glm::dvec3(at(9.0, "Slider")[3]).x == Approx(-1.4));
    // STEP: the keyframe at 0.5 holds until 1.0.
    CHECK(at(0.99, "Blinker")[0][0] == Approx(0.25));
    CHECK(at(1.0, "Blinker")[0][0] == Approx(0.6));
    // CUBICSPLINE: glTF's Hermite spline between keyframes 0 and 1 (values (2, 1, 0) and
    // (2.2, 0.2, 0.5), out-tangent (0, 3, 0), in-tangent (-2, 0, 0), one second apart).
    const double u = 0.3, u2 = u * u, u3 = u2 * u;
    const glm::dvec3 hermite = (2 * u3 - 3 * u2 + 1) * glm::dvec3(2, 1, 0) + (u3 - 2 * u2 + u) * glm::dvec3(0, 3, 0) +
                               (-2 * u3 + 3 * u2) * glm::dvec3(2.2, 0.2, 0.5) + (u3 - u2) * glm::dvec3(-2, 0, 0);
    const glm::dvec3 spline = glm::dvec3(at(0.3, "Spline")[3]);
    CHECK(spline.x == Approx(hermite.x).epsilon(1e-6));
    CHECK(spline.y == Approx(hermite.y).epsilon(1e-6));
    CHECK(spline.z == Approx(hermite.z).epsilon(1e-6));
    // LINEAR rotation by slerp, the short way although the third keyframe has the other sign:
    // half way, the rotation is half of the one between the keyframes.
    const glm::dquat q1 = glm::angleAxis(glm::radians(120.0), glm::dvec3(0, 1, 0));
    const glm::dquat q2 = glm::angleAxis(glm::radians(240.0), glm::normalize(glm::dvec3(0, 1, 0.3)));
    const glm::dquat mid = glm::normalize(glm::quat_cast(glm::dmat3(at(1.5, "Spinner")) / 0.5));
    const double whole = 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(q1, q2))));
    const double half = 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(q1, mid))));
    CHECK(half == Approx(whole / 2).epsilon(1e-5));
    CHECK(whole < glm::pi<double>());
    // The child follows its animated parent; the camera's node moves.
    CHECK(glm::distance(glm::dvec3(at(1.5, "Moon")[3]), glm::dvec3(at(1.5, "Spinner")[3])) ==
          Approx(0.8).epsilon(1e-6));
    CHECK(glm::dvec3(glm::inverse(s.pose(2.0).view)[3]).z == Approx(6.0).epsilon(1e-6));
    CHECK(glm::dvec3(glm::inverse(s.pose(0.0).view)[3]).z == Approx(7.0).epsilon(1e-6));
}

TEST_CASE("glTF: EXT_mesh_gpu_instancing draws the node's mesh once per instance", "[scenes][gltf]") {
    const Scene s = load_scene(kGltf / "instancing.glb");
    REQUIRE(s.objects.size() == 125);
    CHECK(s.meshes.size() == 1);
    // Instance 0's translation (-2, -2, -2) under the node's rotation.
    const glm::dmat4 node = s.objects[0].world_from_object * glm::inverse(s.objects[0].instance);
    CHECK(glm::distance(glm::dvec3(s.objects[0].instance[3]), glm::dvec3(-2.0)) < 1e-6);
    CHECK(glm::distance(glm::dvec3(s.objects[0].world_from_object[3]), glm::dvec3(node * glm::dvec4(-2, -2, -2, 1))) <
          1e-6);
    CHECK(s.objects[124].name == "Instances instance 124");
}

TEST_CASE("glTF: --camera picks a camera by node name, camera name or index, a wrong one lists them",
          "[scenes][gltf][camera]") {
    const auto camera = [](const std::string& name) {
        SceneLoadOptions o;
        o.camera = name;
        return load_scene(kGltf / "cameras.gltf", o).camera;
    };
    CHECK(camera("").name == "Wide");
    CHECK(camera("Top").kind == Camera::Kind::Orthographic);
    CHECK(camera("Top view").name == "Top");
    CHECK(camera("2").name == "Close");
    CHECK_THROWS_WITH(camera("Side"), Catch::Contains("--camera Side") && Catch::Contains("0 'Wide'") &&
                                          Catch::Contains("1 'Top'") && Catch::Contains("2 'Close'"));
    CHECK_THROWS_WITH(camera("7"), Catch::Contains("no camera node"));
    CHECK_THROWS_AS(camera("7"), CameraOptionError);  // the command line's fault: exit 2
}

TEST_CASE("glTF: cameras keep their height and widen, never stretch, the default camera frames the scene at any size",
          "[scenes][gltf][camera]") {
    Camera ortho;
    ortho.kind = Camera::Kind::Orthographic;
    ortho.xmag = 2.0, ortho.ymag = 1.0, ortho.znear = 0.1, ortho.zfar = 10.0;
    // Wider than 2:1: the height is kept, the width follows the image.
    CHECK(ortho.projection(4.0)[1][1] == 1.0);
    CHECK(ortho.projection(4.0)[0][0] == 0.25);
    // Narrower: the width xmag is kept, the height grows; square pixels either way.
    CHECK(ortho.projection(1.0)[0][0] == 0.5);
    CHECK(ortho.projection(1.0)[1][1] == 0.5);
    Camera persp;
    persp.yfov = 1.0, persp.znear = 0.1, persp.zfar = 10.0;
    CHECK(persp.projection(0.5)[1][1] == Approx(1.0 / std::tan(0.5)));  // no aspectRatio: yfov kept
    persp.aspect_ratio = 2.0;
    CHECK(persp.projection(3.0)[1][1] == Approx(1.0 / std::tan(0.5)));
    CHECK(persp.projection(1.0)[0][0] == Approx(1.0 / (2.0 * std::tan(0.5))));  // the camera's width kept
    CHECK(persp.projection(1.0)[1][1] / persp.projection(1.0)[0][0] == Approx(1.0));

    const Scene s = load_scene(kGltf / "assembly.glb");  // no camera
    CHECK(s.camera.name == "the default camera");
    CHECK(s.camera.aspect_ratio == 1.0);
}

TEST_CASE("glTF: transforms are composed in double from the file's numbers, rounded to float once per draw",
          "[scenes][gltf]") {
    // A child 100000 to the left under a parent 100000.03 to the right: 0.03 in double, where
    // float would keep 0.03125 (100000.03 is 100000.03125 in float).
    const auto dir = temp_dir("gltf-double");
    json doc = triangle_file();
    doc["nodes"] = {{{"translation", {100000.03, 0, 0}}, {"children", {1}}},
                    {{"translation", {-100000.0, 0, 0}}, {"mesh", 0}}};
    doc["scenes"][0]["nodes"] = {0};
    write(dir / "far.gltf", doc);
    const Scene s = load_scene(dir / "far.gltf");
    REQUIRE(s.objects.size() == 1);
    CHECK(s.objects[0].world_from_object[3][0] == Approx(0.03).epsilon(1e-9));
    // The draw's matrix is the double product rounded: its translation column holds the 0.03
    // (through the camera framing it), not float's 0.03125.
    const Pose p = s.rest();
    const glm::dmat4 exact = s.camera.projection(1.0) * (p.view * p.world_from_object[0]);
    const glm::mat4 drawn = s.clip_from_object(p, 0, 1.0);
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) CHECK(drawn[c][r] == float(exact[c][r]));
    }
    glm::mat4 float_world(1.0f);
    float_world[3][0] = 100000.03f - 100000.0f;
    CHECK(float_world[3][0] == 0.03125f);
    CHECK(s.objects[0].world_from_object[3][0] != double(float_world[3][0]));
}

TEST_CASE("glTF: extensions required and not implemented are refused, used ones warned once", "[scenes][gltf]") {
    const auto dir = temp_dir("gltf-extensions");
    json doc = triangle_file();
    doc["extensionsUsed"] = {"KHR_materials_emissive_strength", "KHR_texture_transform", "KHR_lights_punctual"};
    write(dir / "used.gltf", doc);
    const Scene s = load_scene(dir / "used.gltf");
    REQUIRE(s.warnings.size() == 1);
    CHECK(s.warnings[0].find("KHR_materials_emissive_strength, KHR_lights_punctual") != std::string::npos);
    doc["extensionsRequired"] = {"KHR_texture_transform", "KHR_lights_punctual", "KHR_draco_mesh_compression"};
    write(dir / "required.gltf", doc);
    CHECK_THROWS_WITH(load_scene(dir / "required.gltf"),
                      Catch::Contains("extensionsRequired[1]: 'KHR_lights_punctual' is required but not implemented") &&
                          Catch::Contains("extensionsRequired[2]: 'KHR_draco_mesh_compression'") &&
                          !Catch::Contains("[0]"));
}

TEST_CASE("glTF: every bad material, accessor and texture is reported in one message", "[scenes][gltf][errors]") {
    const auto dir = temp_dir("gltf-problems");
    json doc = triangle_file();
    // Four primitives: a bad alphaMode, a bad texture reference, a normal accessor out of range,
    // and a good one.
    doc["materials"] = {
        {{"alphaMode", "GLASS"}}, {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 4}}}}}}, json::object()};
    doc["meshes"][0]["primitives"] = {{{"attributes", {{"POSITION", 0}}}, {"material", 0}},
                                      {{"attributes", {{"POSITION", 0}}}, {"material", 1}},
                                      {{"attributes", {{"POSITION", 0}, {"NORMAL", 9}}}, {"material", 2}},
                                      {{"attributes", {{"POSITION", 0}}}, {"material", 2}}};
    write(dir / "bad.gltf", doc);
    try {
        load_scene(dir / "bad.gltf");
        FAIL("loaded");
    } catch (const SceneError& e) {
        const std::string m = e.what();
        INFO(m);
        CHECK(m.find("bad.gltf: materials[0].alphaMode: 'GLASS'") != std::string::npos);
        CHECK(
            m.find("bad.gltf: materials[1].pbrMetallicRoughness.baseColorTexture.index: texture index out of range") !=
            std::string::npos);
        CHECK(m.find("bad.gltf: meshes[0].primitives[2].attributes.NORMAL: accessor index out of range") !=
              std::string::npos);
        CHECK(std::count(m.begin(), m.end(), '\n') == 2);
    }
}

TEST_CASE("glTF: the default material draws what names no shader, with the material's values", "[scenes][gltf]") {
    const Scene s = load_scene(kGltf / "default-material.gltf");
    const Pose p = s.rest();
    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const Object& o = s.objects[i];
        INFO(o.name << " " << o.material);
        CHECK(o.shader.empty());
        std::map<std::string, std::vector<double>> u;
        for (const UniformSetting& x : object_uniforms(s, i, p, 1.6)) u[x.name] = x.values;
        if (o.name == "Flat box") {
            CHECK(o.material == "'Red' (materials[1])");
            CHECK(u["uLighting"] == std::vector<double>{2.0});  // no NORMAL: flat
            CHECK(u["uBaseColorFactor"][0] == Approx(0.8));
        }
        if (o.name == "Textured sphere") CHECK(u["uLighting"] == std::vector<double>{1.0});
        if (o.name == "Unlit sign") CHECK(u["uLighting"] == std::vector<double>{0.0});
        if (o.name == "No material") CHECK(o.material == "meshes[3].primitives[0] (no material)");
    }
    // Rendered without --shader, nothing to warn about (the untextured materials read white).
    Scene scene = load_scene(kGltf / "default-material.gltf");
    const SceneRenderer r(scene, {});
    CHECK(r.notes().empty());
    CHECK(scene.warnings.empty());

    // A catalogue shader sampling teximage on materials without one: white there, said once.
    FrameRequest single;
    single.shader_override = "single_texture";
    const SceneRenderer t(scene, single);
    REQUIRE(t.notes().size() == 2);  // and TEXCOORD_0, which three of its meshes lack
    CHECK(t.notes()[0].find("TEXCOORD_0 missing on 3 primitives of 3 meshes drawn by shaders that read it "
                            "('single_texture')") != std::string::npos);
    CHECK(t.notes()[1].find("shader 'single_texture' samples 'teximage', which 4 materials bind no texture to") !=
          std::string::npos);

    // Materials, not the objects drawing them: the workshop draws some of its untextured materials more than once.
    Scene workshop = load_scene(kGltf / "workshop.gltf");
    std::set<std::string> untextured;
    for (const Object& o : workshop.objects) {
        if (o.texture_for("teximage") < 0) untextured.insert(o.material);
    }
    REQUIRE(untextured.size() == 5);
    const SceneRenderer w(workshop, single);
    REQUIRE(w.notes().size() == 1);
    CHECK(w.notes()[0].find("shader 'single_texture' samples 'teximage', which 5 materials bind no texture to") !=
          std::string::npos);
}

#if defined(QUADSHADE_HAS_RAYCAST)
TEST_CASE("glTF: the ray caster draws the default material as the rasterizer does, posed, and refuses BLEND",
          "[scenes][gltf][raycast]") {
    // Within a step of 1/255 on all but a few pixels (the ray caster's own interpolation, as for
    // every shader: tests/raycast), the flat normals from ray quads' derivatives included.
    for (const auto& [file, time] :
         {std::pair{"default-material.gltf", 0.0}, {"animation.gltf", 1.25}, {"instancing.glb", 0.0}}) {
        Scene s = load_scene(kGltf / file);
        FrameRequest raster, raycast;
        raster.time = raycast.time = time;
        raycast.backend = Backend::RayCaster;
        const Framebuffer a = render_frame(s, raster), b = render_frame(s, raycast);
        std::size_t over = 0, covered = 0;
        for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
            covered += a.rgba[i + 3] > 0.5f;
            for (int c = 0; c < 4; ++c) {
                over += std::abs(int(unorm8(a.rgba[i + std::size_t(c)])) - int(unorm8(b.rgba[i + std::size_t(c)]))) > 1;
            }
        }
        std::printf("ray caster against rasterizer, glTF %s at t = %g: %zu channels over 1/255, %zu covered pixels\n",
                    file, time, over, covered);
        INFO(file);
        CHECK(covered > a.rgba.size() / 4 / 20);
        CHECK(over <= covered / 200);
    }
    Scene blended = load_scene(kGltf / "alpha-modes.gltf");
    FrameRequest raycast;
    raycast.backend = Backend::RayCaster;
    CHECK_THROWS_WITH(render_frame(blended, raycast), Catch::Contains("'Pane 0' (materials[3]): alphaMode BLEND") &&
                                                          Catch::Contains("--backend raster"));
}
#endif

TEST_CASE("glTF: missing texture coordinates are counted in one warning", "[scenes][gltf]") {
    Scene s = load_scene(kGltf / "assembly.glb");  // no TEXCOORD_0 anywhere
    FrameRequest r;
    r.shader_override = "dots";
    const SceneRenderer renderer(s, r);
    REQUIRE(renderer.notes().size() == 1);
    CHECK(renderer.notes()[0].find(
              "TEXCOORD_0 missing on 4 primitives of 3 meshes drawn by shaders that read it ('dots')") !=
          std::string::npos);
}

TEST_CASE("glTF: the command line renders every feature scene by default, and animations frame by frame",
          "[cli][gltf]") {
    const auto dir = temp_dir("gltf-cli");
    for (const char* f :
         {"default-material.gltf", "alpha-modes.gltf", "texcoord-sets.gltf", "primitive-modes.gltf", "animation.gltf",
          "instancing.glb", "quantized.gltf", "cameras.gltf", "workshop.gltf", "assembly.glb"}) {
        const std::string cmd = (kBin / "quadshade").string() + " render " + (kGltf / f).string() +
                                " --size 48x32 -o " + (dir / "out.png").string() + " 2> /dev/null";
        INFO(f);
        CHECK(std::system(cmd.c_str()) == 0);
    }
    // An animation's frames differ where things move.
    const std::string cmd = (kBin / "quadshade").string() + " render " + (kGltf / "animation.gltf").string() +
                            " --size 48x36 --frames 0:2 --fps 2 -o " + (dir / "frame_%d.png").string() +
                            " 2> /dev/null";
    REQUIRE(std::system(cmd.c_str()) == 0);
    auto slurp = [](const std::filesystem::path& p) {
        std::ifstream in(p, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), {});
    };
    CHECK(slurp(dir / "frame_0.png") != slurp(dir / "frame_1.png"));
    CHECK(slurp(dir / "frame_1.png") != slurp(dir / "frame_2.png"));
    const std::string cam = (kBin / "quadshade").string() + " render " + (kGltf / "cameras.gltf").string() +
                            " --camera 'Top view' --size 48x32 -o " + (dir / "top.png").string() + " 2> /dev/null";
    CHECK(std::system(cam.c_str()) == 0);
    CHECK(slurp(dir / "top.png") != slurp(dir / "out.png"));
    // A camera the file does not have is bad usage, like any option the scene cannot take.
    std::string err;
    CHECK(test::run((kBin / "quadshade").string() + " render " + (kGltf / "cameras.gltf").string() +
                        " --camera Side -o " + (dir / "side.png").string(),
                    &err, dir / "side.err") == 2);
    CHECK(err.find("--camera Side: no camera node of that name") != std::string::npos);
    CHECK(!std::filesystem::exists(dir / "side.png"));
}

}  // namespace qs
