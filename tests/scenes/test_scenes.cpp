// Scenes and the command line: shipped assets are reproducible, bad input is refused with the
// file and field named, the CLI's exit codes, and animation frames.
#include <catch2/catch.hpp>

#include <sys/wait.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>
#include <utility>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>
#include <OpenImageIO/imageio.h>

#include "images/image_io.h"
#include "render/scene_render.h"
#include "render/undefined_mask.h"
#include "scenes/gltf.h"
#include "shading/catalogue.h"
#include "shading/number/checked.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;

std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Runs a command line; returns its exit code and what it wrote to stderr.
std::pair<int, std::string> run(const std::string& cmd, const std::filesystem::path& dir) {
    const auto err = dir / "stderr.txt";
    const int status = std::system((cmd + " 2> '" + err.string() + "' > /dev/null").c_str());
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(err)};
}

void write_text(const std::filesystem::path& p, const std::string& text) { std::ofstream(p) << text; }

// A string attribute of an image file's metadata, as OpenImageIO reads it ("" when absent).
std::string image_attribute(const std::filesystem::path& file, const std::string& name) {
    auto in = OIIO::ImageInput::open(file.string());
    return in ? in->spec().get_string_attribute(name) : "(unreadable)";
}

}  // namespace

TEST_CASE("the shipped scenes are exactly what the generator makes", "[scenes]") {
    const auto dir = temp_dir("assets");
    REQUIRE(std::system(((kBin / "quadshade-make-scenes").string() + " " + dir.string()).c_str()) == 0);
    // Every file it makes is committed unchanged, and every committed file is one it makes.
    const auto files = [](const std::filesystem::path& root) {
        std::set<std::string> all;
        for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
            const std::string file = std::filesystem::relative(e.path(), root).string();
            if (e.is_regular_file() && !file.starts_with("models/")) all.insert(file);  // models/: vendored, not made
        }
        return all;
    };
    const std::set<std::string> made = files(dir);
    CHECK(made == files(kSource / "scenes/assets"));
    CHECK(made.count("figure-1.1.gltf"));
    CHECK(made.count("conformance/torus-rolled.gltf"));
    for (const std::string& f : made) {
        INFO(f);
        CHECK(slurp(dir / f) == slurp(kSource / "scenes/assets" / f));
    }
}

TEST_CASE("the Figure 1.1 scene has the chapter's camera, objects and shaders", "[scenes]") {
    const Scene s = load_scene(kFigure);
    CHECK(s.width == 1264);
    CHECK(s.height == 400);
    REQUIRE(s.objects.size() == 5);
    CHECK(s.objects[0].shader == "flow_noise");
    CHECK(s.objects[4].shader == "tiles3d");
    CHECK(s.meshes[s.objects[1].mesh].indices.size() == 1520 * 3);  // 20 bands x 40 steps
    CHECK(s.camera.yfov == Approx(glm::radians(15.0f)));
    CHECK(s.clear_color == glm::vec4(0.0f, 0.3f, 0.5f, 0.0f));
}

TEST_CASE("bad scene input is refused naming the file and the field", "[scenes][errors]") {
    const auto dir = temp_dir("bad");
    SECTION("not JSON") {
        write_text(dir / "a.gltf", "{ this is not json");
        CHECK_THROWS_WITH(load_scene(dir / "a.gltf"), Catch::Contains("a.gltf") && Catch::Contains("not a valid glTF"));
    }
    SECTION("missing file") {
        CHECK_THROWS_WITH(load_scene(dir / "missing.gltf"), Catch::Contains("missing.gltf") && Catch::Contains("no such file"));
    }
    Scene s = load_scene(kPlane);
    copy_textures_into(s, dir);
    SECTION("NaN vertex") {
        s.meshes[0].vertices[2].position.y = std::numeric_limits<float>::quiet_NaN();
        save_scene(s, dir / "nan.gltf");
        CHECK_THROWS_WITH(load_scene(dir / "nan.gltf"),
                          Catch::Contains("nan.gltf") && Catch::Contains("attributes.POSITION") && Catch::Contains("vertex 2"));
    }
    SECTION("index out of range") {
        s.meshes[0].indices[4] = 99;
        save_scene(s, dir / "index.gltf");
        CHECK_THROWS_WITH(load_scene(dir / "index.gltf"), Catch::Contains(".indices") && Catch::Contains("99"));
    }
    SECTION("unknown shader") {
        s.objects[0].shader = "no_such_shader";
        save_scene(s, dir / "shader.gltf");
        Scene loaded = load_scene(dir / "shader.gltf");
        CHECK_THROWS_WITH(render_frame(loaded, {}), Catch::Contains("shader.gltf") && Catch::Contains("extras.shader") &&
                                                        Catch::Contains("no_such_shader"));
    }
    SECTION("missing texture") {
        s.textures[0].image.file = dir / "textures" / "gone.png";
        s.objects[0].shader = "halftone";
        save_scene(s, dir / "tex.gltf");
        Scene loaded = load_scene(dir / "tex.gltf");
        CHECK_THROWS_WITH(render_frame(loaded, {}), Catch::Contains("tex.gltf") &&
                                                        Catch::Contains("materials[0].pbrMetallicRoughness.baseColorTexture") &&
                                                        Catch::Contains("gone.png"));
    }
    SECTION("a texture that is not an image") {
        s.textures[0].image = {{}, {'n', 'o', 't', ' ', 'a', 'n', ' ', 'i', 'm', 'a', 'g', 'e'}, "image/png",
                               ImageSource::Kind::DataUri};
        s.objects[0].shader = "single_texture";
        save_scene(s, dir / "garbage.gltf");
        Scene loaded = load_scene(dir / "garbage.gltf");
        CHECK_THROWS_WITH(render_frame(loaded, {}), Catch::Contains("garbage.gltf") && Catch::Contains("baseColorTexture") &&
                                                        Catch::Contains("data: URI image"));
    }
    SECTION("a shader that samples a texture the material lacks reads white, and says so") {
        s.objects[0].texture = -1;
        s.objects[0].shader = "halftone";
        save_scene(s, dir / "untextured.gltf");
        Scene loaded = load_scene(dir / "untextured.gltf");
        const SceneRenderer r(loaded, {});
        REQUIRE(r.notes().size() == 1);
        CHECK(r.notes()[0].find("untextured.gltf: shader 'halftone' samples 'teximage', which 1 material binds no texture "
                                "to: it reads white (1, 1, 1, 1) there; first: 'plane' (materials[0])") != std::string::npos);
    }
    SECTION("a texture is not read when no drawn shader samples it") {
        s.textures[0].image.file = dir / "textures" / "gone.png";
        save_scene(s, dir / "unused.gltf");
        Scene loaded = load_scene(dir / "unused.gltf");
        CHECK_NOTHROW(render_frame(loaded, {}));
    }
}

TEST_CASE("textures: baseColorTexture, extras.teximage, glTF's sampler defaults, bad samplers and URIs", "[scenes][textures]") {
    const auto dir = temp_dir("sampler");
    std::filesystem::create_directories(dir / "images");
    write_image(dir / "images" / "a b.png", Image{2, 2, std::vector<float>(16, 0.5f)});
    // One triangle; its material's baseColorTexture has a sampler giving only magFilter.
    auto gltf = [&](const std::string& material, const std::string& sampler, const std::string& image_uri) {
        return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
            "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
            "materials": [)" + material + R"(],
            "textures": [{"source": 0, "sampler": 0}], "samplers": [)" + sampler + R"(],
            "images": [{"uri": ")" + image_uri + R"("}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [-1, -1, 0], "max": [1, 1, 0]}],
            "bufferViews": [{"buffer": 0, "byteLength": 36}],
            "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAAAAAAAAgD8AAAAA"}]})";
    };
    const std::string base = R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}, "extras": {"shader": "single_texture"}})";
    SECTION("baseColorTexture, its URI percent-decoded, glTF's defaults where the sampler is silent") {
        write_text(dir / "a.gltf", gltf(base, R"({"magFilter": 9728})", "images/a%20b.png"));
        const Scene s = load_scene(dir / "a.gltf");
        REQUIRE(s.objects[0].texture == 0);
        const Texture& t = s.textures[0];
        CHECK(t.image.file == dir / "images" / "a b.png");
        CHECK(t.sampler.mag_filter == Filter::Nearest);
        CHECK(t.sampler.min_filter == Filter::LinearMipmapLinear);  // no glTF default: the usual auto filtering
        CHECK(t.sampler.wrap_s == Wrap::Repeat);                     // glTF's default
        CHECK(t.sampler.wrap_t == Wrap::Repeat);
        Scene r = s;
        CHECK_NOTHROW(render_frame(r, {}));
    }
    SECTION("extras.teximage names another file, with baseColorTexture's sampler") {
        const std::string m = R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}},
                                  "extras": {"shader": "single_texture", "teximage": "images/other.png"}})";
        write_text(dir / "b.gltf", gltf(m, R"({"wrapS": 33071})", "images/a%20b.png"));
        const Scene s = load_scene(dir / "b.gltf");
        REQUIRE(s.textures.size() == 1);
        CHECK(s.textures[0].image.file == dir / "images" / "other.png");
        CHECK(s.textures[0].sampler.wrap_s == Wrap::ClampToEdge);
    }
    SECTION("an unknown wrap mode") {
        write_text(dir / "c.gltf", gltf(base, R"({"wrapT": 1234})", "images/a%20b.png"));
        CHECK_THROWS_WITH(load_scene(dir / "c.gltf"), Catch::Contains("c.gltf") && Catch::Contains("samplers[0].wrapT") &&
                                                          Catch::Contains("1234"));
    }
    SECTION("an unknown filter") {
        write_text(dir / "d.gltf", gltf(base, R"({"minFilter": 9999})", "images/a%20b.png"));
        CHECK_THROWS_WITH(load_scene(dir / "d.gltf"), Catch::Contains("samplers[0].minFilter") && Catch::Contains("9999"));
    }
    SECTION("an absolute URI") {
        write_text(dir / "e.gltf", gltf(base, "{}", "/etc/outside.png"));
        CHECK_THROWS_WITH(load_scene(dir / "e.gltf"), Catch::Contains("e.gltf") && Catch::Contains("images[0].uri") &&
                                                          Catch::Contains("/etc/outside.png"));
    }
    SECTION("a required extension quadshade does not implement") {
        std::string text = gltf(base, "{}", "images/a%20b.png");
        text.insert(1, R"("extensionsUsed": ["KHR_draco_mesh_compression"], "extensionsRequired": ["KHR_draco_mesh_compression"],)");
        write_text(dir / "g.gltf", text);
        CHECK_THROWS_WITH(load_scene(dir / "g.gltf"), Catch::Contains("extensionsRequired[0]") &&
                                                          Catch::Contains("KHR_draco_mesh_compression"));
    }
    SECTION("a second texture coordinate set: the default material reads it") {
        const std::string m = R"({"pbrMetallicRoughness": {"baseColorTexture": {"index": 0, "texCoord": 1}}})";
        write_text(dir / "f.gltf", gltf(m, "{}", "images/a%20b.png"));
        CHECK(load_scene(dir / "f.gltf").objects[0].look.texcoord == 1);
    }
}

TEST_CASE("textures: extras.textures binds samplers by name: textures[] indices, files, 3D volumes", "[scenes][textures]") {
    const auto dir = temp_dir("named-textures");
    std::filesystem::create_directories(dir / "images");
    write_image(dir / "images" / "flat.png", Image{4, 2, std::vector<float>(32, 0.5f)});
    write_image(dir / "images" / "volume.png", Image{4, 12, std::vector<float>(4 * 12 * 4, 0.25f)});  // 3 slices of 4x4
    auto gltf = [&](const std::string& extras) {
        return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
            "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
            "materials": [{"extras": )" + extras + R"(}],
            "textures": [{"source": 0, "sampler": 0}], "samplers": [{"wrapS": 33071}, {"minFilter": 9728, "wrapT": 33648},
                                                           {"minFilter": 9729, "magFilter": 9729}],
            "images": [{"uri": "images/volume.png"}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [-1, -1, 0], "max": [1, 1, 0]}],
            "bufferViews": [{"buffer": 0, "byteLength": 36}],
            "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAAAAAAAAgD8AAAAA"}]})";
    };
    SECTION("an index, a file and a volume with its depth, sampler and wrapR; saved and loaded the same") {
        write_text(dir / "a.gltf", gltf(R"({"shader": "fast_noise", "textures": {
            "uIndexed": 0, "uFile": "images/flat.png",
            "noise3dSampler": {"image": "images/volume.png", "depth": 3, "sampler": 1, "wrapR": 33071}}})"));
        Scene s = load_scene(dir / "a.gltf");
        const Object& o = s.objects[0];
        REQUIRE(o.samplers.size() == 3);
        const Texture& indexed = s.textures[std::size_t(o.texture_for("uIndexed"))];
        CHECK(indexed.dims == 2);
        CHECK(indexed.sampler.wrap_s == Wrap::ClampToEdge);  // textures[0]'s sampler
        const Texture& file = s.textures[std::size_t(o.texture_for("uFile"))];
        CHECK(file.image.file == dir / "images" / "flat.png");
        CHECK(file.sampler == Sampler{});  // glTF's defaults
        const Texture& volume = s.textures[std::size_t(o.texture_for("noise3dSampler"))];
        CHECK(volume.dims == 3);
        CHECK(volume.depth == 3);
        CHECK(volume.sampler.min_filter == Filter::Nearest);  // samplers[1]
        CHECK(volume.sampler.wrap_t == Wrap::MirroredRepeat);
        CHECK(volume.sampler.wrap_r == Wrap::ClampToEdge);
        CHECK(o.texture_for("teximage") == -1);
        CHECK(o.texture_for("nothing") == -1);
        CHECK_NOTHROW(render_frame(s, {}));  // fast_noise samples noise3dSampler as a 4x4x3 volume

        save_scene(s, dir / "saved.gltf");
        const Scene again = load_scene(dir / "saved.gltf");
        const Texture& v2 = again.textures[std::size_t(again.objects[0].texture_for("noise3dSampler"))];
        CHECK(v2.dims == 3);
        CHECK(v2.depth == 3);
        CHECK(v2.sampler == volume.sampler);
        CHECK(v2.image.file == volume.image.file);
    }
    SECTION("a depth comparison texture for a sampler2DShadow; saved and loaded the same; the two kinds not mixed") {
        write_text(dir / "shadow.frag", "#version 130\nin vec2 st;\nout vec4 c;\nuniform sampler2DShadow depth;\n"
                                        "void main() { c = vec4(texture(depth, vec3(st, 0.5))); }\n");
        write_text(dir / "d.gltf", gltf(R"({"glsl": "shadow.frag", "textures": {
            "depth": {"image": "images/flat.png", "sampler": 2, "compare": "GEQUAL"}}})"));
        Scene s = load_scene(dir / "d.gltf");
        const Texture& depth = s.textures[std::size_t(s.objects[0].texture_for("depth"))];
        CHECK(depth.compare == CompareFunc::GreaterEqual);
        CHECK_NOTHROW(render_frame(s, {}));
        save_scene(s, dir / "saved-depth.gltf");
        const Scene again = load_scene(dir / "saved-depth.gltf");
        CHECK(again.textures[std::size_t(again.objects[0].texture_for("depth"))].compare == CompareFunc::GreaterEqual);
        // glTF's default sampler (trilinear) gives it float mipmaps, and its lookups a level of detail
        write_text(dir / "mipmapped.gltf", gltf(R"({"glsl": "shadow.frag", "textures": {
            "depth": {"image": "images/flat.png", "compare": "LESS"}}})"));
        Scene mipmapped = load_scene(dir / "mipmapped.gltf");
        CHECK_NOTHROW(render_frame(mipmapped, {}));

        write_text(dir / "plain.gltf", gltf(R"({"glsl": "shadow.frag", "textures": {"depth": "images/flat.png"}})"));
        Scene plain = load_scene(dir / "plain.gltf");
        CHECK_THROWS_WITH(render_frame(plain, {}),
                          Catch::Contains("plain.gltf") && Catch::Contains("sampler2DShadow 'depth'") &&
                              Catch::Contains("not a depth comparison texture"));
        write_text(dir / "colour.frag", "#version 130\nin vec2 st;\nout vec4 c;\nuniform sampler2D depth;\n"
                                        "void main() { c = texture(depth, st); }\n");
        write_text(dir / "mixed.gltf", gltf(R"({"glsl": "colour.frag", "textures": {
            "depth": {"image": "images/flat.png", "sampler": 2, "compare": "LEQUAL"}}})"));
        Scene mixed = load_scene(dir / "mixed.gltf");
        CHECK_THROWS_WITH(render_frame(mixed, {}),
                          Catch::Contains("mixed.gltf") && Catch::Contains("is a depth comparison texture"));
    }
    SECTION("a cube map of six faces for a samplerCube and, compared, a samplerCubeShadow; saved and loaded the same") {
        for (int f = 0; f < 6; ++f) {
            write_image(dir / "images" / ("face" + std::to_string(f) + ".png"), Image{4, 4, std::vector<float>(64, 0.1f * float(f))});
        }
        write_image(dir / "images" / "big.png", Image{8, 8, std::vector<float>(256, 0.5f)});
        const std::string faces = R"(["images/face0.png", "images/face1.png", "images/face2.png", "images/face3.png",
                                      "images/face4.png", "images/face5.png"])";
        write_text(dir / "cube.frag", "#version 130\nin vec2 st;\nout vec4 c;\nuniform samplerCube env;\n"
                                      "void main() { c = texture(env, vec3(st * 2.0 - 1.0, 0.5)); }\n");
        write_text(dir / "cube.gltf", gltf(R"({"glsl": "cube.frag", "textures": {"env": {"faces": )" + faces + "}}}"));
        Scene s = load_scene(dir / "cube.gltf");
        const Texture& cube = s.textures[std::size_t(s.objects[0].texture_for("env"))];
        CHECK(cube.dims == kCubeMap);
        REQUIRE(cube.faces.size() == 6);
        CHECK(cube.faces[3].file == dir / "images" / "face3.png");
        CHECK_NOTHROW(render_frame(s, {}));
        save_scene(s, dir / "saved-cube.gltf");
        const Scene again = load_scene(dir / "saved-cube.gltf");
        const Texture& cube2 = again.textures[std::size_t(again.objects[0].texture_for("env"))];
        CHECK(cube2.dims == kCubeMap);
        CHECK(cube2.faces == cube.faces);
        CHECK(cube2.sampler == cube.sampler);

        write_text(dir / "cube-shadow.frag", "#version 130\nin vec2 st;\nout vec4 c;\nuniform samplerCubeShadow env;\n"
                                             "void main() { c = vec4(texture(env, vec4(st * 2.0 - 1.0, 0.5, st.x))); }\n");
        write_text(dir / "cube-depth.gltf", gltf(R"({"glsl": "cube-shadow.frag", "textures": {"env": {"faces": )" + faces +
                                                 R"(, "sampler": 2, "compare": "NOTEQUAL"}}})"));
        Scene depth = load_scene(dir / "cube-depth.gltf");
        CHECK(depth.textures[std::size_t(depth.objects[0].texture_for("env"))].compare == CompareFunc::NotEqual);
        CHECK_NOTHROW(render_frame(depth, {}));
        save_scene(depth, dir / "saved-cube-depth.gltf");
        CHECK(load_scene(dir / "saved-cube-depth.gltf").textures.at(0).compare == CompareFunc::NotEqual);

        // What the faces' images are, and which sampler reads which kind, is checked where a shader
        // samples them, naming the field, the face and the sampler.
        const auto with_face = [&](int face, const std::string& file) {
            std::string f = faces;
            const std::string name = "images/face" + std::to_string(face) + ".png";
            f.replace(f.find(name), name.size(), file);
            return f;
        };
        const std::pair<std::string, const char*> bad[] = {
            {R"({"glsl": "cube.frag", "textures": {"env": {"faces": )" + with_face(3, "images/flat.png") + "}}}",
             "extras.textures.env.faces[3] (face -Y): a 4x2 image: a cube map's faces are square"},
            {R"({"glsl": "cube.frag", "textures": {"env": {"faces": )" + with_face(5, "images/big.png") + "}}}",
             "extras.textures.env.faces[5] (face -Z): a 8x8 image where face +X is 4x4"},
            {R"({"glsl": "cube.frag", "textures": {"env": {"faces": )" + with_face(1, "images/missing.png") + "}}}",
             "extras.textures.env.faces[1] (face -X)"},
            {R"({"glsl": "cube.frag", "textures": {"env": "images/flat.png"}})",
             "samples a samplerCube 'env' but materials[0].extras.textures.env is a 2D texture"},
            {R"({"glsl": "shadow.frag", "textures": {"depth": {"faces": )" + faces + R"(, "sampler": 2, "compare": "LEQUAL"}}})",
             "samples a sampler2DShadow 'depth' but materials[0].extras.textures.depth.faces is a cube map"},
            {R"({"glsl": "cube-shadow.frag", "textures": {"env": {"faces": )" + faces + "}}}",
             "samples a samplerCubeShadow 'env' but materials[0].extras.textures.env.faces is not a depth comparison texture"},
            {R"({"glsl": "cube.frag", "textures": {"env": {"faces": )" + faces + R"(, "sampler": 2, "compare": "LEQUAL"}}})",
             "is a depth comparison texture, for a samplerCubeShadow"},
        };
        write_text(dir / "shadow.frag", "#version 130\nin vec2 st;\nout vec4 c;\nuniform sampler2DShadow depth;\n"
                                        "void main() { c = vec4(texture(depth, vec3(st, 0.5))); }\n");
        for (const auto& [extras, message] : bad) {
            INFO(extras);
            write_text(dir / "bad-cube.gltf", gltf(extras));
            Scene b = load_scene(dir / "bad-cube.gltf");
            CHECK_THROWS_WITH(render_frame(b, {}), Catch::Contains("bad-cube.gltf") && Catch::Contains(message));
        }
    }
    SECTION("teximage by name") {
        write_text(dir / "b.gltf", gltf(R"({"shader": "single_texture", "textures": {"teximage": "images/flat.png"}})"));
        Scene s = load_scene(dir / "b.gltf");
        REQUIRE(s.objects[0].texture >= 0);
        CHECK(s.textures[std::size_t(s.objects[0].texture)].image.file == dir / "images" / "flat.png");
        CHECK(s.objects[0].samplers.empty());
        CHECK_NOTHROW(render_frame(s, {}));
    }
    SECTION("bad bindings are refused, naming the field") {
        const std::pair<const char*, const char*> bad[] = {
            {R"({"textures": [1]})", "extras.textures"},
            {R"({"textures": {"1bad": 0}})", "not a GLSL identifier"},
            {R"({"textures": {"u": 7}})", "extras.textures.u"},
            {R"({"textures": {"u": {"image": "images/flat.png", "texture": 0}}})", "exactly one of"},
            {R"({"textures": {"u": {"image": "images/flat.png", "depth": 0}}})", "extras.textures.u.depth"},
            {R"({"textures": {"u": {"image": "images/flat.png", "wrapR": 33071}}})", "only a 3D texture"},
            {R"({"textures": {"u": {"image": "images/flat.png", "depth": 2, "wrapR": 1}}})", "extras.textures.u.wrapR"},
            {R"({"textures": {"u": {"image": "images/flat.png", "filter": 1}}})", "extras.textures.u.filter"},
            {R"({"textures": {"u": {"image": "/etc/passwd"}}})", "extras.textures.u.image"},
            {R"({"teximage": "images/flat.png", "textures": {"teximage": 0}})", "bound twice"},
            {R"({"textures": {"teximage": {"texture": 0, "depth": 3}}})", "sampler2D"},
            {R"({"textures": {"u": {"image": "images/flat.png", "sampler": 2, "compare": "LESS_EQUAL"}}})",
             "extras.textures.u.compare"},
            {R"({"textures": {"u": {"image": "images/flat.png", "sampler": 2, "compare": 515}}})",
             "expected a compare function"},
            {R"({"textures": {"u": {"image": "images/flat.png", "sampler": 2, "depth": 2, "compare": "LEQUAL"}}})",
             "is 2D"},
            {R"({"textures": {"u": {"faces": ["images/flat.png", "images/flat.png"]}}})",
             "extras.textures.u.faces: expected an array of six image files"},
            {R"({"textures": {"u": {"faces": ["a.png", "b.png", 3, "d.png", "e.png", "f.png"]}}})",
             "extras.textures.u.faces[2]"},
            {R"({"textures": {"u": {"faces": ["a.png"], "image": "images/flat.png"}}})", "exactly one of"},
            {R"({"textures": {"u": {"faces": ["a.png"], "depth": 2}}})", "a cube map (faces) has no depth"},
            {R"({"textures": {"teximage": {"faces": ["a.png", "b.png", "c.png", "d.png", "e.png", "f.png"]}}})",
             "teximage is a sampler2D"},
        };
        for (const auto& [extras, message] : bad) {
            INFO(extras);
            write_text(dir / "bad.gltf", gltf(extras));
            CHECK_THROWS_WITH(load_scene(dir / "bad.gltf"), Catch::Contains("bad.gltf") && Catch::Contains(message));
        }
    }
    SECTION("a shader's sampler unbound reads white, and says so once") {
        write_text(dir / "unbound.gltf", gltf(R"({"shader": "fast_noise"})"));
        Scene s = load_scene(dir / "unbound.gltf");
        const SceneRenderer r(s, {});
        REQUIRE(r.notes().size() == 1);
        CHECK(r.notes()[0].find("shader 'fast_noise' samples 'noise3dSampler', which 1 material binds no texture to: it "
                                "reads white") != std::string::npos);
    }
    SECTION("a shader's sampler of the other kind, or a volume whose rows do not divide into its depth") {
        const std::pair<const char*, const char*> bad[] = {
            {R"({"shader": "fast_noise", "textures": {"noise3dSampler": 0}})", "is a 2D texture"},
            {R"({"shader": "fast_noise", "textures": {"noise3dSampler": {"texture": 0, "depth": 5}}})", "does not stack 5 slices"},
        };
        for (const auto& [extras, message] : bad) {
            INFO(extras);
            write_text(dir / "unbound.gltf", gltf(extras));
            Scene s = load_scene(dir / "unbound.gltf");
            CHECK_THROWS_WITH(render_frame(s, {}), Catch::Contains("unbound.gltf") && Catch::Contains(message));
        }
    }
}

TEST_CASE("any glTF mesh renders with any catalogue shader, camera or not", "[scenes]") {
    // A minimal hand-written file: one triangle, no camera, no material, buffer inline.
    const auto dir = temp_dir("user");
    write_text(dir / "tri.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [-1, -1, 0], "max": [1, 1, 0]}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAAAAAAAAgD8AAAAA"}]})");
    Scene s = load_scene(dir / "tri.gltf");
    CHECK_NOTHROW(render_frame(s, {}));  // without a material: the default material
    for (const Program* p : catalogue()) {
        if (samples_textures(p->info().needs)) continue;  // no texture in this file
        // These write a value (a derivative, a probe's result), not coverage, to alpha.
        static const std::set<std::string_view> kValueInAlpha = {
            "st_derivative_probe", "position_derivative_probe", "integer_probe", "integer_undefined_probe",
            "bool_probe", "loop_probe", "discard_probe", "matrix_probe", "builtins_probe", "uniform_probe", "sin_cos_probe"};
        if (kValueInAlpha.count(p->info().name)) continue;
        FrameRequest r;
        r.width = r.height = 32;
        r.shader_override = std::string(p->info().name);
        const Framebuffer fb = render_frame(s, r);
        std::size_t drawn = 0;
        for (std::size_t i = 3; i < fb.rgba.size(); i += 4) drawn += fb.rgba[i] > 0.5f;
        INFO(p->info().name);
        // The framed triangle, seen from the default camera's three-quarter view, covers about a
        // seventh of the view (150 pixels).
        CHECK(drawn > 110);
    }
}

TEST_CASE("node hierarchies compose as glTF says: parent matrix times the child's T R S", "[scenes]") {
    // A root with a matrix (90 degrees about z, then moved by (1, 2, 3)), its child by TRS:
    // moved by (0.5, 0, 0), turned 90 degrees about x, scaled (2, 3, 4). The mesh is the child's.
    const auto dir = temp_dir("hierarchy");
    write_text(dir / "h.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"matrix": [0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1], "children": [1]},
                  {"translation": [0.5, 0, 0], "rotation": [0.70710678, 0, 0, 0.70710678], "scale": [2, 3, 4], "mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [-1, -1, 0], "max": [1, 1, 0]}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAAAAAAAAgD8AAAAA"}]})");
    const Scene s = load_scene(dir / "h.gltf");
    REQUIRE(s.objects.size() == 1);
    const glm::mat4& m = s.objects[0].world_from_object;
    // Worked by hand: S, then R (x, y, z) -> (x, -z, y), then T, then the root's (x, y, z) ->
    // (1 - y, 2 + x, 3 + z).
    const std::pair<glm::vec3, glm::vec3> cases[] = {{{0, 0, 0}, {1, 2.5f, 3}}, {{1, 0, 0}, {1, 4.5f, 3}},
                                                     {{1, 1, 1}, {5, 4.5f, 6}}, {{0, 0, 1}, {5, 2.5f, 3}}};
    for (const auto& [object, world] : cases) {
        const glm::vec4 w = m * glm::vec4(object, 1.0f);
        INFO(object.x << " " << object.y << " " << object.z << " -> " << w.x << " " << w.y << " " << w.z);
        CHECK(w.x == Approx(world.x).margin(1e-6));
        CHECK(w.y == Approx(world.y).margin(1e-6));
        CHECK(w.z == Approx(world.z).margin(1e-6));
        CHECK(w.w == 1.0f);
    }
}

TEST_CASE("glTF's doubleSided: back faces culled unless it is true, front faces clockwise under a mirroring node", "[scenes][culling]") {
    // One triangle, counter-clockwise seen from the framing camera (+z), under a node that keeps
    // it, turns it around (180 degrees about y) or mirrors it in z (the same points, but the
    // determinant is negative, so its front faces are clockwise: it is seen from behind). Its
    // texture coordinates wind clockwise: an atlas bake must draw it anyway.
    const auto dir = temp_dir("culling");
    const std::string nodes[] = {R"({"mesh": 0})", R"({"mesh": 0, "rotation": [0, 1, 0, 0]})", R"({"mesh": 0, "scale": [1, 1, -1]})"};
    const bool kDrawnSingleSided[] = {true, false, false};
    for (int n = 0; n < 3; ++n) {
        for (const char* material : {"", R"(, "material": 0)"}) {
            for (const bool double_sided : {false, true}) {
                if (!*material && double_sided) continue;  // no material: glTF's default, single-sided
                const std::string materials = *material ? std::string(R"("materials": [{"doubleSided": )") +
                                                              (double_sided ? "true" : "false") + "}],"
                                                        : "";
                write_text(dir / "t.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
                    "nodes": [)" + nodes[n] + R"(], )" + materials + R"(
                    "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1})" + material + R"(}]}],
                    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                                   "min": [-1, -1, 0], "max": [1, 1, 0]},
                                  {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}],
                    "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24}],
                    "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAAAAAAAAgD8AAAAAzczMPc3MzD3NzMw9ZmZmP2ZmZj/NzMw9"}]})");
                Scene s = load_scene(dir / "t.gltf");
                REQUIRE(s.objects.size() == 1);
                CHECK(s.objects[0].double_sided == double_sided);
                CHECK(s.objects[0].mirrors() == (n == 2));
                // The pixels a 32x32 frame of `checker` covers.
                const auto covered = [&](Backend backend, bool atlas) {
                    FrameRequest r;
                    r.width = r.height = 32;
                    r.shader_override = "checker";
                    r.backend = backend;
                    r.atlas = atlas;
                    const Framebuffer fb = render_frame(s, r);
                    std::size_t drawn = 0;
                    for (std::size_t i = 3; i < fb.rgba.size(); i += 4) drawn += fb.rgba[i] > 0.5f;
                    return drawn;
                };
                const bool expected = double_sided || kDrawnSingleSided[n];
                for (const Backend backend : {Backend::Rasterizer, Backend::RayCaster}) {
                    const std::size_t drawn = covered(backend, false);
                    INFO("node " << n << (*material ? " with" : " without") << " a material, doubleSided " << double_sided
                                 << ", backend " << int(backend));
                    CHECK((drawn > 110) == expected);  // about 150 pixels where drawn
                    CHECK((drawn == 0) == !expected);
                }
                // An atlas bake draws every triangle whatever its material says.
                CHECK(covered(Backend::Rasterizer, true) > 0);
            }
        }
    }
    // save_scene writes doubleSided back.
    Scene s = load_scene(dir / "t.gltf");
    s.objects[0].shader = "checker";
    save_scene(s, dir / "saved.gltf");
    CHECK(load_scene(dir / "saved.gltf").objects[0].double_sided);
}

TEST_CASE("frames differ where the shader depends on time and nowhere else", "[scenes][animation]") {
    Scene fig = load_scene(kFigure);
    FrameRequest r;
    r.width = 316, r.height = 100;
    std::vector<Framebuffer> frames;
    for (float t : {0.0f, 1.0f / 30.0f, 2.0f / 30.0f}) {
        r.time = t;
        frames.push_back(render_frame(fig, r));
    }
    std::size_t background = 0, object = 0, object_changed = 0;
    for (std::size_t p = 0; p < frames[0].rgba.size(); p += 4) {
        const bool drawn = frames[0].rgba[p + 3] == 1.0f;
        const bool changed = frames[0].rgba[p] != frames[1].rgba[p] || frames[1].rgba[p] != frames[2].rgba[p] ||
                             frames[0].rgba[p + 1] != frames[2].rgba[p + 1];
        if (!drawn) {
            ++background;
            CHECK_FALSE(changed);  // the clear colour does not move
        } else {
            ++object;
            object_changed += changed;
        }
    }
    CHECK(background > 0);
    CHECK(object_changed > object * 9 / 10);  // every Figure 1.1 shader animates
    // A shader without time is identical frame to frame.
    Scene plane = load_scene(kPlane);
    FrameRequest a, b;
    a.width = b.width = a.height = b.height = 64;
    a.time = 0.0f, b.time = 5.0f;
    a.shader_override = b.shader_override = "perlin";
    CHECK(render_frame(plane, a).rgba == render_frame(plane, b).rgba);
}

TEST_CASE("leaving out what a shader does not use (gl_FragCoord, helper lanes, depth) changes no colour",
          "[scenes][specialisation]") {
    // The general path interpolates gl_FragCoord for every shader and shades everything in quads
    // with a depth buffer: a shader that read gl_FragCoord without declaring it would differ here.
    // At 200x136 the plane fills the frame, so the lean path also takes its whole-tile shortcut
    // (no coverage tests in 64x64 tiles inside a triangle), which the depth-tested path never does.
    Scene plane = load_scene(kPlane);
    for (const Program* p : catalogue()) {
        if (samples_textures(p->info().needs)) continue;  // the plane has no texture
        INFO(p->info().name);
        FrameRequest r;
        r.width = 200, r.height = 136;
        r.shader_override = std::string(p->info().name);
        const Framebuffer lean = render_frame(plane, r);
        r.raster.force_general_path = true;
        const Framebuffer general = render_frame(plane, r);
        REQUIRE(lean.rgba.size() == general.rgba.size());
        CHECK(std::memcmp(lean.rgba.data(), general.rgba.data(), lean.rgba.size() * sizeof(float)) == 0);
    }
}

TEST_CASE("scenes drawn in painter's order, without a depth buffer, are the depth-tested frames to the bit",
          "[scenes][depth]") {
    // Figure 1.1 and the ProcTexGen spheres: culled spheres drawn after the ground behind them, which
    // the rasterizer proves needs no depth buffer (raster/depth_buffer.h); the general path tests
    // every depth. Several sizes, so that the spheres' silhouettes snap differently.
    for (const auto& path : {kFigure, kProcTexGenSpheres}) {
        Scene scene = load_scene(path);
        for (const auto& [w, h] : {std::pair{632, 200}, std::pair{1264, 400}, std::pair{701, 333}}) {
            INFO(path.filename().string() << " at " << w << "x" << h);
            FrameRequest r;
            r.width = w, r.height = h;
            const Framebuffer lean = render_frame(scene, r);
            r.raster.force_general_path = true;
            const Framebuffer tested = render_frame(scene, r);
            CHECK(lean.depth.empty());
            CHECK_FALSE(tested.depth.empty());
            REQUIRE(lean.rgba.size() == tested.rgba.size());
            CHECK(std::memcmp(lean.rgba.data(), tested.rgba.data(), lean.rgba.size() * sizeof(float)) == 0);
        }
    }
}

TEST_CASE("the command line: exit codes, messages, no partial output", "[cli]") {
    const auto dir = temp_dir("cli");
    const std::string qs = (kBin / "quadshade").string();
    const std::string out = (dir / "out.png").string();
    SECTION("success writes the image") {
        auto [code, err] = run(qs + " render " + kPlane.string() + " --size 32x32 -o " + out, dir);
        CHECK(code == 0);
        CHECK(err.find("frame") != std::string::npos);
        CHECK(read_image(out).width == 32);
    }
    SECTION("bad usage is exit 2") {
        CHECK(run(qs + " render", dir).first == 2);
        CHECK(run(qs + " render " + kPlane.string() + " -o " + out + " --size 10", dir).first == 2);
        CHECK(run(qs + " render " + kPlane.string() + " -o " + out + " --derivatives sideways", dir).first == 2);
        CHECK(run(qs + " frobnicate", dir).first == 2);
        CHECK_FALSE(std::filesystem::exists(out));
    }
    SECTION("bad input is exit 1, names the culprit, and writes nothing") {
        auto [code, err] = run(qs + " render " + kPlane.string() + " --shader nope -o " + out, dir);
        CHECK(code == 1);
        CHECK(err.find("unknown shader 'nope'") != std::string::npos);
        auto [code2, err2] = run(qs + " render " + (dir / "none.gltf").string() + " -o " + out, dir);
        CHECK(code2 == 1);
        CHECK(err2.find("none.gltf") != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(out));
        // An unwritable destination leaves no partial file behind.
        auto [code3, err3] = run(qs + " render " + kPlane.string() + " --size 8x8 -o " + (dir / "no/dir/x.png").string(), dir);
        CHECK(code3 == 1);
        CHECK(err3.find("no folder") != std::string::npos);
        CHECK(std::distance(std::filesystem::directory_iterator(dir), {}) == 1);  // just stderr.txt
    }
    SECTION("options no backend honours together are exit 2, named, before anything is read or written") {
        // The scene does not exist: reading it would be exit 1 naming it.
        const std::string missing = (dir / "missing.gltf").string(), mask = (dir / "mask.png").string();
        const auto refused = [&](const std::string& options, const std::string& message) {
            auto [code, err] = run(qs + " render " + missing + " -o " + out + " " + options, dir);
            INFO(options << " -> " << err);
            CHECK(code == 2);
            CHECK(err.find(message) != std::string::npos);
            CHECK(err.find("missing.gltf") == std::string::npos);
            CHECK_FALSE(std::filesystem::exists(out));
            CHECK_FALSE(std::filesystem::exists(mask));
        };
        refused("--precision double --derivatives coarse-lower",
                "--derivatives coarse-lower --precision double: double precision is shaded with the fine");
        refused("--derivatives coarse-upper --precision double", "not with a coarse rule");
        refused("--derivatives analytic --undefined-mask " + mask,
                "--derivatives analytic --precision float --undefined-mask: checking for undefined GLSL cases");
        refused("--precision double --undefined-mask " + mask, "checking for undefined GLSL cases shades in float");
        // The rasterizer's own options, even at their defaults: the ray caster has none of them.
        for (const char* option : {"--fill-rule right-top", "--fill-rule left-bottom", "--interpolation separate",
                                   "--interpolation fused", "--general-path"}) {
            const std::string name = std::string(option).substr(0, std::string(option).find(' '));
            refused(std::string("--backend raycast ") + option, name + ": a rasterizer option");
        }
        // The same options are the rasterizer's to take, and --quad-pairing is both backends'.
        CHECK(run(qs + " render " + kPlane.string() + " --size 8x8 --precision double --general-path -o " + out, dir).first == 0);
#if defined(QUADSHADE_HAS_RAYCAST)
        CHECK(run(qs + " render " + kPlane.string() + " --size 8x8 --backend raycast --quad-pairing bottom-up -o " + out,
                  dir).first == 0);
#endif
    }
    SECTION("the image's metadata records every setting that decides its pixels") {
        auto [code, err] = run(qs + " render " + kPlane.string() + " --size 16x16 --shader halftone --precision double "
                                   "--quad-pairing bottom-up --fill-rule right-top --interpolation separate --time 2 -o " + out,
                               dir);
        REQUIRE(code == 0);
        CHECK(image_attribute(out, "quadshade:precision") == "double");
        CHECK(image_attribute(out, "quadshade:derivatives") == "fine");
        CHECK(image_attribute(out, "quadshade:quad_pairing") == "bottom-up");
        CHECK(image_attribute(out, "quadshade:fill_rule") == "right-top");
        CHECK(image_attribute(out, "quadshade:interpolation") == "separate");
        CHECK(image_attribute(out, "quadshade:backend") == "raster");
        CHECK(image_attribute(out, "quadshade:shader") == "halftone");
        CHECK(image_attribute(out, "quadshade:time") == "2.000000");
        const std::string floats = (dir / "float.png").string();
        REQUIRE(run(qs + " render " + kPlane.string() + " --size 16x16 --shader uniform_probe --uniform uScale=2.5 -o " +
                        floats, dir).first == 0);
        CHECK(image_attribute(floats, "quadshade:precision") == "float");
        CHECK(image_attribute(floats, "quadshade:uniforms") == "uScale=2.5");
        CHECK(image_attribute(floats, "quadshade:interpolation") != "");
    }
    SECTION("an animation writes numbered frames") {
        auto [code, err] = run(qs + " render " + kFigure.string() + " --size 64x20 --frames 3:5 --fps 10 -o " +
                                   (dir / "f.png").string(), dir);
        CHECK(code == 0);
        for (const char* f : {"f_0003.png", "f_0004.png", "f_0005.png"}) CHECK(std::filesystem::exists(dir / f));
        CHECK(slurp(dir / "f_0003.png") != slurp(dir / "f_0004.png"));
    }
    SECTION("--backend raycast renders, reports its BVH, and rejects unknown backends") {
#if defined(QUADSHADE_HAS_RAYCAST)
        auto [code, err] = run(qs + " render " + kFigure.string() + " --size 64x20 --backend raycast -o " + out, dir);
        CHECK(code == 0);
        CHECK(err.find("BVH built once") != std::string::npos);
        CHECK(read_image(out).width == 64);
#else
        auto [code, err] = run(qs + " render " + kFigure.string() + " --size 64x20 --backend raycast -o " + out, dir);
        CHECK(code == 1);
        CHECK(err.find("QUADSHADE_RAYCAST") != std::string::npos);
#endif
        CHECK(run(qs + " render " + kFigure.string() + " --backend sideways -o " + out, dir).first == 2);
    }
    SECTION("shaders lists the catalogue with what each needs") {
        const auto list = dir / "list.txt";
        CHECK(std::system((qs + " shaders > " + list.string()).c_str()) == 0);
        const std::string text = slurp(list);
        CHECK(text.find("halftone") != std::string::npos);
        CHECK(text.find("derivatives") != std::string::npos);
    }
    SECTION("compare exits 3 over its threshold") {
        run(qs + " render " + kPlane.string() + " --size 16x16 --shader perlin -o " + (dir / "a.png").string(), dir);
        run(qs + " render " + kPlane.string() + " --size 16x16 --shader worley -o " + (dir / "b.png").string(), dir);
        CHECK(run(qs + " compare " + (dir / "a.png").string() + " " + (dir / "a.png").string(), dir).first == 0);
        CHECK(run(qs + " compare " + (dir / "a.png").string() + " " + (dir / "b.png").string(), dir).first == 3);
    }
}

}  // namespace qs

namespace qs {

TEST_CASE("long animations: float time freezes and jumps near 1e6 s, --stable-time keeps every frame", "[animation][stability]") {
    Scene scene = load_scene(kFigure);
    FrameRequest r;
    r.width = 158, r.height = 50;  // an eighth of the figure: enough to see every object move
    SceneRenderer plain(scene, r);
    r.stable_time = true;
    SceneRenderer stable(scene, r);
    const double start = 1e6;
    std::vector<decltype(Framebuffer::rgba)> plain_frames, stable_frames;
    double worst_time_error = 0.0;
    for (int f = 0; f < 30; ++f) {  // one second at 30 frames per second
        const double t = start + f / 30.0;
        worst_time_error = std::max(worst_time_error, std::abs(double(float(t)) - t));
        Framebuffer fb;
        plain.render_into(fb, t);
        plain_frames.push_back(fb.rgba);
        stable.render_into(fb, t);
        stable_frames.push_back(fb.rgba);
    }
    auto distinct = [](const std::vector<decltype(Framebuffer::rgba)>& frames) {
        std::size_t n = 1;
        for (std::size_t i = 1; i < frames.size(); ++i) n += frames[i] != frames[i - 1];
        return n;
    };
    std::printf("long animations at t = 1e6 s, 30 frames at 30 fps: float time gives %zu distinct frames (time off by "
                "up to %.3f s), stable time %zu\n", distinct(plain_frames), worst_time_error, distinct(stable_frames));
    CHECK(distinct(plain_frames) < 20);  // float spacing at 1e6 is 1/16 s: frames repeat
    CHECK(distinct(stable_frames) == 30);

    // With stable time each object sees its time modulo its period: the spots sphere alone at
    // 1e6 s is the same image as at 1e6 mod 289 s.
    std::erase_if(scene.objects, [](const Object& o) { return o.shader != "spots"; });
    FrameRequest spots = r;
    SceneRenderer wrapped(scene, spots);
    spots.stable_time = false;
    SceneRenderer small(scene, spots);
    Framebuffer a, b;
    wrapped.render_into(a, start + 0.5);
    small.render_into(b, std::fmod(start + 0.5, 289.0));
    CHECK(a.rgba == b.rgba);
}

}  // namespace qs

namespace qs {

TEST_CASE("the ground plane at the horizon: derivatives of 1e4 texels per pixel, no NaN, halftone flat, aastep aliases",
          "[stability][derivatives]") {
    // The Table 1.1 plane made 2000 units wide, st scaled with it, seen from 0.5 above: towards
    // the horizon one pixel spans thousands of pattern cells.
    Scene s = load_scene(kPlane);
    for (Vertex& v : s.meshes[0].vertices) v.texcoord *= 1000.0f;
    s.objects[0].world_from_object = glm::scale(glm::mat4(1.0f), glm::vec3(1000.0f, 1000.0f, 1.0f));
    s.camera.kind = Camera::Kind::Perspective;
    s.camera.yfov = glm::radians(40.0f);
    s.camera.znear = 0.05f, s.camera.zfar = 5000.0f;
    s.camera.view = glm::lookAt(glm::vec3(0.0f, -990.0f, 0.5f), glm::vec3(0.0f, 0.0f, 0.3f), glm::vec3(0.0f, 0.0f, 1.0f));
    FrameRequest r;
    r.width = 256, r.height = 128;
    r.shader_override = "st_derivative_probe";
    const Framebuffer d = render_frame(s, r);
    double largest = 0.0;
    int largest_row = 0;
    for (int y = 0; y < d.height; ++y) {
        for (int x = 0; x < d.width; ++x) {
            const float* p = d.pixel(x, y);
            const double w = std::max(std::abs(p[0]) + std::abs(p[2]), std::abs(p[1]) + std::abs(p[3]));  // fwidth
            if (w > largest) largest = w, largest_row = y;
        }
    }
    // The halftone's texture is 512 texels across st's unit: texels per pixel = 512 fwidth(st).
    std::printf("horizon: largest fwidth(st) %.4g (%.4g halftone texels per pixel) at row %d of %d\n", largest,
                512.0 * largest, largest_row, d.height);
    CHECK(512.0 * largest > 1e3);

    // The row of the largest derivative is the plane's far edge; the statistics below use the
    // first row under it that the plane covers from side to side.
    auto row_stats = [&](const Framebuffer& f) {
        int row = largest_row;
        auto full = [&](int y) {
            for (int x = 0; x < f.width; ++x) {
                if (f.pixel(x, y)[3] == 0.0f) return false;
            }
            return true;
        };
        while (row + 1 < f.height && !full(row)) ++row;
        double sum = 0.0, sum2 = 0.0;
        for (int x = 0; x < f.width; ++x) {
            const double v = f.pixel(x, row)[0];
            sum += v, sum2 += v * v;
        }
        const double mean = sum / f.width;
        return std::pair(mean, std::sqrt(std::max(0.0, sum2 / f.width - mean * mean)));
    };
    for (const char* shader : {"dots_aa", "halftone", "worley_tiles"}) {
        r.shader_override = shader;
        const Framebuffer f = render_frame(s, r);
        std::size_t nan = 0;
        for (float v : f.rgba) nan += !std::isfinite(v);
        const auto [mean, spread] = row_stats(f);
        std::printf("horizon: %-12s no NaN: %s; red on the horizon row: mean %.3f, spread %.3f\n", shader,
                    nan == 0 ? "yes" : "NO", mean, spread);
        INFO(shader);
        CHECK(nan == 0);
        // The halftone blends to the texture's colour once fwidth(st) passes 1.4/200: flat.
        if (std::string(shader) == "halftone") CHECK(spread < 0.05);
        // aastep does not fade to grey here: its width is the derivative of the *pattern value*,
        // length(fract(5 st) - 0.5), whose neighbour differences stay below its range (0.7) however
        // many cells a pixel spans, so the ramp never covers the value range and the row stays
        // noise. Measured: spread 0.35. A documented limit of aastep, not of quadshade.
        if (std::string(shader) == "dots_aa") CHECK(spread > 0.2);
    }
}

}  // namespace qs

namespace qs {

namespace {
constexpr std::uint8_t kNaN = std::uint8_t(Undefined::NaN);
constexpr std::uint8_t kDivision = std::uint8_t(Undefined::DivisionByZero);
constexpr std::uint8_t kArgument = std::uint8_t(Undefined::Argument);

Framebuffer render_checked(Scene& scene, const std::string& shader, int width, int height, bool check,
                           Backend backend = Backend::Rasterizer) {
    FrameRequest r;
    r.width = width, r.height = height;
    r.shader_override = shader;
    r.backend = backend;
    r.shading.check_undefined = check;
    return render_frame(scene, r);
}
}  // namespace

TEST_CASE("the undefined-case mask flags each of the float environment probe's columns with its own cases",
          "[undefined][stability]") {
    // float_env_probe, column x (see shaders/probes.h): 0 normalize(vec3(0)), 1 inversesqrt(0),
    // 2 pow(-2, 1.5), 3 mod(1, 0), 4 a denormal (defined), 5 sqrt(-1), 6 log(0), 7.. 0 * inversesqrt(0).
    const std::uint8_t expected[8] = {kArgument | kNaN, kArgument, kArgument | kNaN, kDivision | kNaN, 0,
                                      kArgument | kNaN, kArgument, kArgument | kNaN};
    Scene plane = load_scene(kPlane);
    std::vector<Backend> backends = {Backend::Rasterizer};
#if defined(QUADSHADE_HAS_RAYCAST)
    backends.push_back(Backend::RayCaster);
#endif
    for (Backend backend : backends) {
        const Framebuffer fb = render_checked(plane, "float_env_probe", 12, 6, true, backend);
        REQUIRE(fb.undefined.size() == 12 * 6);
        for (int row = 0; row < fb.height; ++row) {
            for (int x = 0; x < fb.width; ++x) {
                INFO("backend " << int(backend) << ", column " << x << ", row " << row);
                CHECK(int(fb.undefined[std::size_t(row * fb.width + x)]) == int(expected[std::min(x, 7)]));
            }
        }
    }
    // The select that stands for GLSL's if/else chain keeps each column to its own case: no
    // column carries the cases of the branches GLSL does not run there.
}

TEST_CASE("the undefined-case mask: aastep with a zero derivative is flagged, and checking never changes a colour",
          "[undefined][stability]") {
    Scene plane = load_scene(kPlane);
    SECTION("smoothstep(e - w, e + w, x) with w = 0 everywhere") {
        const Framebuffer fb = render_checked(plane, "smoothstep_probe", 16, 8, true);
        for (std::uint8_t u : fb.undefined) CHECK(int(u) == int(kArgument));
    }
    SECTION("every catalogue shader on the plane, and Figure 1.1's own, give the same colours checked") {
        for (const Program* p : catalogue()) {
            if (samples_textures(p->info().needs)) continue;  // the plane has no texture
            const std::string name(p->info().name);
            INFO(name);
            const Framebuffer plain = render_checked(plane, name, 40, 24, false);
            const Framebuffer checked = render_checked(plane, name, 40, 24, true);
            CHECK(plain.undefined.empty());
            CHECK(std::memcmp(plain.rgba.data(), checked.rgba.data(), plain.rgba.size() * sizeof(float)) == 0);
            std::size_t cases[3] = {}, pixels = 0;
            for (std::uint8_t u : checked.undefined) {
                pixels += u != 0;
                for (int k = 0; k < 3; ++k) cases[k] += (u >> k) & 1u;
            }
            if (pixels > 0) {
                std::printf("undefined-case mask, plane 40x24: %-20s %4zu of %d pixels (NaN %zu, division by zero %zu, "
                            "outside a built-in's domain %zu)\n",
                            name.c_str(), pixels, 40 * 24, cases[0], cases[1], cases[2]);
            }
        }
        Scene fig = load_scene(kFigure);
        const Framebuffer plain = render_checked(fig, "", 158, 50, false);
        const Framebuffer checked = render_checked(fig, "", 158, 50, true);
        CHECK(std::memcmp(plain.rgba.data(), checked.rgba.data(), plain.rgba.size() * sizeof(float)) == 0);
        // Figure 1.1 hits no undefined case; the clear colour is never flagged.
        CHECK(std::all_of(checked.undefined.begin(), checked.undefined.end(), [](std::uint8_t u) { return u == 0; }));
    }
    SECTION("bricks_aa: at a brick's centre the gradient of b vanishes on one row of the quad") {
        // b = max(|fract(8s - ...) - 0.5|, ...) has a symmetric peak there: aastep's width is 0.
        const Framebuffer fb = render_checked(plane, "bricks_aa", 256, 256, true);
        const auto flagged = std::count(fb.undefined.begin(), fb.undefined.end(), kArgument);
        CHECK(flagged > 0);
        CHECK(flagged == std::count_if(fb.undefined.begin(), fb.undefined.end(), [](std::uint8_t u) { return u != 0; }));
    }
    SECTION("checking refuses analytic derivatives and double precision") {
        FrameRequest r;
        r.width = r.height = 8;
        r.shading.check_undefined = true;
        r.shading.derivatives = Derivatives::Analytic;
        CHECK_THROWS_WITH(render_frame(plane, r), Catch::Contains("not analytic"));
        r.shading.derivatives = Derivatives::Fine;
        r.shading.precision = Precision::Double;
        CHECK_THROWS_WITH(render_frame(plane, r), Catch::Contains("not double"));
    }
}

TEST_CASE("the command line writes the undefined-case mask and counts it", "[undefined][cli]") {
    const auto dir = temp_dir("mask");
    const std::string qs = (kBin / "quadshade").string();
    const std::string base = qs + " render " + kPlane.string() + " --shader float_env_probe --size 12x4 -o " +
                             (dir / "out.png").string();
    SECTION("a PNG: red NaN, green division by zero, blue outside a built-in's domain") {
        auto [code, err] = run(base + " --undefined-mask " + (dir / "mask.png").string(), dir);
        CHECK(code == 0);
        CHECK(err.find("undefined GLSL cases on 44 pixels: NaN produced 36, division by zero 4, built-in outside its "
                       "domain 40") != std::string::npos);
        const Image mask = read_image(dir / "mask.png");
        auto rgb = [&](int x) { return std::array<float, 3>{mask.rgba[4 * x], mask.rgba[4 * x + 1], mask.rgba[4 * x + 2]}; };
        CHECK(rgb(1) == std::array<float, 3>{0, 0, 1});  // inversesqrt(0)
        CHECK(rgb(3) == std::array<float, 3>{1, 1, 0});  // mod(1, 0)
        CHECK(rgb(4) == std::array<float, 3>{0, 0, 0});  // a denormal is defined
        CHECK(rgb(5) == std::array<float, 3>{1, 0, 1});  // sqrt(-1)
    }
    SECTION("refused with analytic derivatives, before writing anything") {
        auto [code, err] = run(base + " --derivatives analytic --undefined-mask " + (dir / "mask.png").string(), dir);
        CHECK(code == 2);
        CHECK(err.find("--undefined-mask") != std::string::npos);
        CHECK_FALSE(std::filesystem::exists(dir / "out.png"));
        CHECK_FALSE(std::filesystem::exists(dir / "mask.png"));
    }
}

TEST_CASE("the undefined-case mask shows integer overflow grey, under the other cases' colours", "[undefined]") {
    constexpr std::uint8_t kOverflow = std::uint8_t(Undefined::Overflow);
    Framebuffer fb;
    fb.width = fb.height = fb.rows = 4;
    fb.undefined = {kOverflow, std::uint8_t(kOverflow | kNaN), kNaN, std::uint8_t(kOverflow | kDivision | kArgument)};
    fb.undefined.resize(16);
    const Image mask = undefined_mask_image(fb);
    auto rgb = [&](int x) {
        return std::array<float, 3>{mask.rgba[4 * x], mask.rgba[4 * x + 1], mask.rgba[4 * x + 2]};
    };
    CHECK(rgb(0) == std::array<float, 3>{0.5f, 0.5f, 0.5f});
    CHECK(rgb(1) == std::array<float, 3>{1, 0.5f, 0.5f});
    CHECK(rgb(2) == std::array<float, 3>{1, 0, 0});
    CHECK(rgb(3) == std::array<float, 3>{0.5f, 1, 1});
    CHECK(rgb(4) == std::array<float, 3>{0, 0, 0});
    const UndefinedCounts counts = count_undefined(fb);
    CHECK(counts.pixels == 4);
    CHECK(counts.per_case == std::array<std::uint64_t, kUndefinedCases>{2, 1, 1, 3});
}

namespace {

// The Table 1.1 plane drawn with uniform_probe, its material setting `uniforms`.
std::filesystem::path uniform_scene(const std::filesystem::path& dir, const std::string& name, std::vector<UniformSetting> uniforms) {
    Scene s = load_scene(kPlane);
    for (Object& o : s.objects) o.shader = "uniform_probe", o.uniforms = uniforms;
    test::copy_textures_into(s, dir);
    const auto file = dir / name;
    save_scene(s, file);
    return file;
}

}  // namespace

TEST_CASE("uniforms: the material's extras.uniforms round-trip through glTF, bad ones name the file and field", "[scenes][uniforms]") {
    const auto dir = temp_dir("uniforms-gltf");
    const auto file = uniform_scene(dir, "set.gltf", {{"uScale", {6.5}, ""}, {"uTint", {0.25, 1.0, 0.75}, ""}});
    const Scene s = load_scene(file);
    REQUIRE(s.objects.at(0).uniforms.size() == 2);
    const UniformSetting& tint = s.objects[0].uniforms[1];  // by name: uScale, uTint
    CHECK(tint.name == "uTint");
    CHECK(tint.values == std::vector<double>{0.25, 1.0, 0.75});
    CHECK(tint.origin == file.string() + ": materials[0].extras.uniforms.uTint");
    // Malformed values are refused by the loader.
    auto refused = [&](const std::string& extras_json, const std::string& field) {
        std::string text = slurp(file);
        const std::size_t at = text.find("\"uniforms\"");
        REQUIRE(at != std::string::npos);
        const std::size_t end = text.find('}', at);
        text.replace(at, end + 1 - at, "\"uniforms\": " + extras_json);
        const auto bad = dir / "bad.gltf";
        write_text(bad, text);
        INFO(extras_json);
        try {
            load_scene(bad);
            FAIL("loaded");
        } catch (const SceneError& e) {
            CHECK(std::string(e.what()).find(field) != std::string::npos);
        }
    };
    refused("[1, 2]", "materials[0].extras.uniforms: expected an object");
    refused("{\"uScale\": \"big\"}", "materials[0].extras.uniforms.uScale: expected a number");
    refused("{\"uTint\": [1, \"x\", 2]}", "materials[0].extras.uniforms.uTint[1]: expected a number");
    refused("{\"uResolution\": [1, 2]}", "materials[0].extras.uniforms.uResolution");
    refused("{\"2x\": 1}", "is not a GLSL uniform name");
}

TEST_CASE("uniforms: --uniform parsing, and the renderer's checks of names and types", "[scenes][uniforms]") {
    const UniformSetting a = parse_uniform_option("uTint=[1, 0.5,0.2]");
    CHECK(a.name == "uTint");
    CHECK(a.values == std::vector<double>{1.0, 0.5, 0.2});
    CHECK(parse_uniform_option("uScale=-4e-1").values == std::vector<double>{-0.4});
    for (const char* bad : {"uScale", "uScale=", "uScale=abc", "uScale=1,,2", "=1", "gl_Foo=1", "uScale=inf", "uResolution=1,2",
                            "uM=1,2,3,4,5,6,7,8,9,10,11,12,13,14,15,16,17"}) {
        INFO(bad);
        CHECK_THROWS_AS(parse_uniform_option(bad), UniformOptionError);
    }
    const auto dir = temp_dir("uniforms-render");
    FrameRequest r;
    r.width = r.height = 8;
    auto render_with = [&](std::vector<UniformSetting> material, std::vector<UniformSetting> options) {
        Scene s = load_scene(uniform_scene(dir, "u.gltf", std::move(material)));
        r.uniforms = std::move(options);
        return render_frame(s, r);
    };
    auto message = [&](auto&& f) -> std::string {
        try {
            f();
        } catch (const std::exception& e) {
            return e.what();
        }
        return "";
    };
    // A material's unknown name or wrong type: bad input, naming the field.
    CHECK_THROWS_AS(render_with({{"uNope", {1.0}, "u.gltf: materials[0].extras.uniforms.uNope"}}, {}), SceneError);
    CHECK(message([&] { render_with({{"uNope", {1.0}, ""}}, {}); })
              .find((dir / "u.gltf").string() + ": materials[0].extras.uniforms.uNope: shader 'uniform_probe' declares no uniform "
                    "'uNope' (it declares: float uScale, vec3 uTint, int uBands, ivec2 uCells, uint uSeed, mat2 uRotate, mat3 uWarp)") !=
          std::string::npos);
    CHECK(message([&] { render_with({{"uBands", {2.5}, "F: f"}}, {}); }).find("uniform 'uBands' of shader 'uniform_probe' is int: 2.5") != std::string::npos);
    CHECK_THROWS_AS(render_with({{"uTint", {1.0, 2.0}, "F: f"}}, {}), SceneError);
    CHECK_THROWS_AS(render_with({{"uSeed", {-1.0}, "F: f"}}, {}), SceneError);
    // The command line's: bad usage.
    CHECK_THROWS_AS(render_with({}, {parse_uniform_option("uNope=1")}), UniformOptionError);
    CHECK_THROWS_AS(render_with({}, {parse_uniform_option("uCells=1,2,3")}), UniformOptionError);
    // --uniform replaces the material's value; the values change the image.
    const Framebuffer initial = render_with({}, {});
    const Framebuffer material = render_with({{"uTint", {0.0, 0.0, 1.0}, "F: f"}}, {});
    const Framebuffer option = render_with({{"uTint", {0.0, 0.0, 1.0}, "F: f"}}, {parse_uniform_option("uTint=0,0,1")});
    const Framebuffer other = render_with({{"uTint", {0.0, 0.0, 1.0}, "F: f"}}, {parse_uniform_option("uTint=1,0,0")});
    CHECK(initial.rgba != material.rgba);
    CHECK(material.rgba == option.rgba);
    CHECK(other.rgba != material.rgba);
    CHECK(material.pixel(3, 3)[0] == 0.0f);
    CHECK(other.pixel(3, 3)[0] > 0.0f);
}

TEST_CASE("uniforms: quadshade render --uniform, exit 2 for a bad option, exit 1 for a bad material", "[cli][uniforms]") {
    const auto dir = temp_dir("uniforms-cli");
    const std::string qs = (kBin / "quadshade").string();
    const std::string out = (dir / "out.png").string();
    const auto good = uniform_scene(dir, "good.gltf", {{"uScale", {2.0}, ""}});
    CHECK(run(qs + " render " + good.string() + " --size 16x16 -o " + out + " --uniform uTint=0,1,0 --uniform 'uWarp=[1,0,0, 0,1,0, 0.5,0,1]'", dir).first == 0);
    auto [code, err] = run(qs + " render " + good.string() + " --size 16x16 -o " + out + " --uniform uNope=1", dir);
    CHECK(code == 2);
    CHECK(err.find("--uniform uNope=1: no shader in this scene declares a uniform 'uNope'") != std::string::npos);
    CHECK(run(qs + " render " + good.string() + " -o " + out + " --uniform uBands=1.5", dir).first == 2);
    CHECK(run(qs + " render " + good.string() + " -o " + out + " --uniform uBands", dir).first == 2);
    CHECK(run(qs + " render " + good.string() + " -o " + out + " --uniform", dir).first == 2);
    const auto bad = uniform_scene(dir, "bad.gltf", {{"uScale", {1.0, 2.0}, ""}});
    auto [code2, err2] = run(qs + " render " + bad.string() + " -o " + (dir / "bad.png").string(), dir);
    CHECK(code2 == 1);
    CHECK(err2.find("materials[0].extras.uniforms.uScale: uniform 'uScale' of shader 'uniform_probe' is float: expected 1 number(s), got 2") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "bad.png"));
}

}  // namespace qs
