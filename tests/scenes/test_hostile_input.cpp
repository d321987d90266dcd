// Hostile and careless input (docs/reliability.md): every case is refused with a message naming
// the file and the field, a non-zero exit and no partial or overwritten output; none crashes,
// hangs, reads outside the scene's folder or allocates what the input merely claims.
#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <thread>

#include <nlohmann/json.hpp>

#include "images/image_io.h"
#include "render/frame_pattern.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "scenes/gltf_checks.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;
using json = nlohmann::json;
namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void write_file(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

// Runs a shell command line; returns its exit code (-signal when killed) and its stderr.
std::pair<int, std::string> run(const std::string& cmd, const fs::path& dir) {
    const auto err = dir / "stderr.txt";
    const int status = std::system((cmd + " 2> '" + err.string() + "' > /dev/null").c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return {code, slurp(err)};
}

const std::string kQuadshade = (kBin / "quadshade").string();

// tri.bin: positions (36 bytes), texcoords (24), uint32 indices (12).
std::string triangle_bin() {
    const float data[15] = {-1, -1, 0, 1, -1, 0, 0, 1, 0, 0, 0, 1, 0, 0.5f, 1};
    const std::uint32_t idx[3] = {0, 1, 2};
    std::string bytes(reinterpret_cast<const char*>(data), sizeof data);
    bytes.append(reinterpret_cast<const char*>(idx), sizeof idx);
    return bytes;
}

// One triangle seen by a camera, drawn with the dots shader; tests break one part of it. (The
// tests here use Table 1.1's shaders, which sanitizer builds compile too.)
json triangle_scene() {
    return json::parse(R"({
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]}],
        "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.1, "zfar": 100}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "indices": 2, "material": 0}]}],
        "materials": [{"extras": {"shader": "dots"}}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"},
                      {"bufferView": 2, "componentType": 5125, "count": 3, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                        {"buffer": 0, "byteOffset": 36, "byteLength": 24},
                        {"buffer": 0, "byteOffset": 60, "byteLength": 12}],
        "buffers": [{"uri": "tri.bin", "byteLength": 72}]})");
}

// Writes `scene` as dir/name with tri.bin beside it; returns the .gltf's path.
fs::path save(const fs::path& dir, const json& scene, const std::string& name = "scene.gltf") {
    write_file(dir / "tri.bin", triangle_bin());
    write_file(dir / name, scene.dump());
    return dir / name;
}

std::string load_error(const fs::path& file, const SceneLoadOptions& options = {}) {
    try {
        load_scene(file, options);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "(loaded)";
}

std::string render_error(const fs::path& file, FrameRequest request = {}) {
    try {
        Scene s = load_scene(file);
        request.width = request.height = 16;
        render_frame(s, request);
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(rendered)";
}

// A PNG whose header claims width x height (its one pixel's data does not matter: the size is
// refused first). The IHDR chunk's CRC is recomputed so that the header itself is valid.
std::string png_claiming(int width, int height, const fs::path& dir) {
    write_image(dir / "one.png", Image{1, 1, {0.5f, 0.5f, 0.5f, 1.0f}});
    std::string png = slurp(dir / "one.png");
    auto put32 = [&](std::size_t at, std::uint32_t v) {
        for (int i = 0; i < 4; ++i) png[at + std::size_t(i)] = char(v >> (24 - 8 * i));
    };
    put32(16, std::uint32_t(width)), put32(20, std::uint32_t(height));
    std::uint32_t crc = 0xFFFFFFFFu;  // CRC-32 of the chunk type and data, bytes 12..28
    for (std::size_t i = 12; i < 29; ++i) {
        crc ^= std::uint8_t(png[i]);
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    put32(29, ~crc);
    return png;
}

bool has_temporaries(const fs::path& dir) {
    for (const auto& e : fs::directory_iterator(dir)) {
        if (e.path().filename().string().rfind('.', 0) == 0) return true;
    }
    return false;
}

}  // namespace

TEST_CASE("hostile input: the test triangle itself loads and renders", "[hostile]") {
    const auto dir = temp_dir("hostile-ok");
    CHECK(render_error(save(dir, triangle_scene())) == "(rendered)");
}

TEST_CASE("accessor and buffer view bounds are checked in arithmetic that cannot wrap", "[hostile][accessors]") {
    const auto dir = temp_dir("hostile-accessors");
    json s = triangle_scene();
    SECTION("an accessor byteOffset near 2^64") {
        s["accessors"][0]["byteOffset"] = 18446744073709551608ull;
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("scene.gltf") && Catch::Contains("accessors[0]") &&
                                                 Catch::Contains("reach past the end of bufferViews[0]"));
    }
    SECTION("a 1 GiB offset whose count would wrap the old end computation") {
        s["accessors"][0]["byteOffset"] = 1073741824;
        s["accessors"][0]["count"] = 1537228672809129302ull;  // 12 * count + 2^30 wraps to 64-bit
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("accessors[0].count") && Catch::Contains("more than"));
    }
    SECTION("a count of 2^62 is refused before anything is allocated") {
        s["accessors"][2]["count"] = 4611686018427387904ull;
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("accessors[2].count") && Catch::Contains("more than the"));
    }
    SECTION("a buffer view whose offset + length wraps") {
        s["bufferViews"][0]["byteOffset"] = 18446744073709551612ull;
        s["bufferViews"][0]["byteLength"] = 8;
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("bufferViews[0]") && Catch::Contains("reach past the end of buffers[0]"));
    }
    SECTION("a stride glTF does not allow") {
        s["bufferViews"][0]["byteStride"] = 3;
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("scene.gltf") && Catch::Contains("byteStride"));
    }
    SECTION("sparse data: indices past the count, negative offsets, values past the view") {
        write_file(dir / "sparse.bin", std::string("\x07\x00\x00\x00", 4) + std::string(12, '\0'));
        s["buffers"].push_back({{"uri", "sparse.bin"}, {"byteLength", 16}});
        s["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 0}, {"byteLength", 4}});
        s["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 4}, {"byteLength", 12}});
        s["accessors"][0]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", 3}, {"componentType", 5125}}},
                                       {"values", {{"bufferView", 4}}}};
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("accessors[0].sparse.indices") && Catch::Contains("index 7"));
        s["accessors"][0]["sparse"]["indices"]["byteOffset"] = -4;
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("sparse.indices.byteOffset") && Catch::Contains("negative"));
        s["accessors"][0]["sparse"]["indices"]["byteOffset"] = 0;
        s["accessors"][0]["sparse"]["values"]["byteOffset"] = 4;
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("accessors[0].sparse.values") && Catch::Contains("reach past"));
    }
    SECTION("valid sparse data replaces the elements it names") {
        const float moved[3] = {0.0f, 0.5f, 0.0f};
        write_file(dir / "sparse.bin", std::string("\x02\x00\x00\x00", 4) + std::string(reinterpret_cast<const char*>(moved), 12));
        s["buffers"].push_back({{"uri", "sparse.bin"}, {"byteLength", 16}});
        s["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 0}, {"byteLength", 4}});
        s["bufferViews"].push_back({{"buffer", 1}, {"byteOffset", 4}, {"byteLength", 12}});
        s["accessors"][0]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", 3}, {"componentType", 5125}}},
                                       {"values", {{"bufferView", 4}}}};
        const Scene loaded = load_scene(save(dir, s));
        CHECK(loaded.meshes[0].vertices[2].position == glm::vec3(0.0f, 0.5f, 0.0f));
        CHECK(loaded.meshes[0].vertices[1].position == glm::vec3(1.0f, -1.0f, 0.0f));
    }
    SECTION("the arithmetic itself") {
        using gltf_checks::strided_end;
        CHECK(strided_end(18446744073709551608ull, 1, 12, 12) == std::nullopt);
        CHECK(strided_end(1ull << 30, 1537228672809129302ull, 12, 12) == std::nullopt);
        CHECK(strided_end(8, 3, 16, 12) == std::optional<std::uint64_t>(8 + 2 * 16 + 12));
        CHECK(strided_end(5, 0, 16, 12) == std::optional<std::uint64_t>(5));
    }
}

TEST_CASE("deep JSON is refused before any parser recurses into it", "[hostile][json]") {
    const auto dir = temp_dir("hostile-json");
    json s = triangle_scene();
    s["materials"][0]["extras"]["deep"] = 1;
    std::string text = s.dump();
    const std::string nested = std::string(100000, '[') + std::string(100000, ']');
    text.replace(text.find("\"deep\":1") + 7, 1, nested);
    write_file(dir / "tri.bin", triangle_bin());
    write_file(dir / "deep.gltf", text);
    CHECK_THAT(load_error(dir / "deep.gltf"), Catch::Contains("deep.gltf") && Catch::Contains("deeper than 64"));
    // Brackets inside strings are text, not nesting.
    s["materials"][0]["extras"]["deep"] = std::string(5000, '[');
    CHECK(load_error(save(dir, s)) == "(loaded)");
}

TEST_CASE("binary glTF: the container's lengths are checked", "[hostile][glb]") {
    const auto dir = temp_dir("hostile-glb");
    json s = triangle_scene();
    s["buffers"][0].erase("uri");
    std::string j = s.dump();
    while (j.size() % 4) j += ' ';
    const std::string bin = triangle_bin();
    auto u32 = [](std::uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
    const std::string glb = "glTF" + u32(2) + u32(std::uint32_t(12 + 8 + j.size() + 8 + bin.size())) + u32(std::uint32_t(j.size())) +
                            "JSON" + j + u32(std::uint32_t(bin.size())) + std::string("BIN\0", 4) + bin;
    write_file(dir / "ok.glb", glb);
    CHECK(load_error(dir / "ok.glb") == "(loaded)");
    std::string bad = glb;
    bad.replace(12, 4, u32(0xFFFFFFF0u));  // JSON chunk length past the end
    write_file(dir / "long.glb", bad);
    CHECK_THAT(load_error(dir / "long.glb"), Catch::Contains("long.glb") && Catch::Contains("header"));
    write_file(dir / "short.glb", glb.substr(0, 15));
    CHECK_THAT(load_error(dir / "short.glb"), Catch::Contains("short.glb") && Catch::Contains("shorter than its header"));
    write_file(dir / "fake.glb", j);
    CHECK_THAT(load_error(dir / "fake.glb"), Catch::Contains("fake.glb") && Catch::Contains("magic"));
}

TEST_CASE("a scene reads only files in its own folder unless allowed", "[hostile][paths]") {
    const auto root = temp_dir("hostile-paths");
    const auto dir = root / "scene";
    fs::create_directories(dir);
    write_file(root / "outside.bin", triangle_bin());
    json s = triangle_scene();
    SECTION("../ and absolute buffer URIs") {
        s["buffers"][0]["uri"] = "../outside.bin";
        const fs::path file = save(dir, s);
        CHECK_THAT(load_error(file), Catch::Contains("buffers[0].uri") && Catch::Contains("leads outside the scene's folder"));
        SceneLoadOptions allow;
        allow.paths.allow_outside = true;
        CHECK(load_error(file, allow) == "(loaded)");
        s["buffers"][0]["uri"] = (root / "outside.bin").string();
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("buffers[0].uri") && Catch::Contains("absolute path"));
        CHECK(load_error(save(dir, s), allow) == "(loaded)");
    }
    SECTION("a symlink inside the folder that leads out") {
        fs::create_symlink(root / "outside.bin", dir / "link.bin");
        s["buffers"][0]["uri"] = "link.bin";
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("buffers[0].uri") && Catch::Contains("leads outside"));
    }
    SECTION("network and other URI schemes") {
        for (const char* uri : {"http://example.com/tri.bin", "HTTPS://example.com/tri.bin"}) {
            s["buffers"][0]["uri"] = uri;
            CHECK_THAT(load_error(save(dir, s)), Catch::Contains("buffers[0].uri") && Catch::Contains("network address"));
        }
        s["buffers"][0]["uri"] = "file:///etc/passwd";
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("buffers[0].uri") && Catch::Contains("URI scheme"));
        s["buffers"][0]["uri"] = "tri.bin";
        s["images"] = json::array({{{"uri", "https://example.com/x.png"}}});
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("images[0].uri") && Catch::Contains("network address"));
    }
    SECTION("a buffer URI naming a folder") {
        fs::create_directories(dir / "folder.bin");
        s["buffers"][0]["uri"] = "folder.bin";
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("folder.bin") && Catch::Contains("is a folder"));
    }
    SECTION("the working directory is never searched") {
        const auto elsewhere = root / "cwd";
        fs::create_directories(elsewhere);
        write_file(elsewhere / "only-here.bin", triangle_bin());
        s["buffers"][0]["uri"] = "only-here.bin";
        const fs::path file = save(dir, s);
        auto [code, err] = run("cd '" + elsewhere.string() + "' && " + kQuadshade + " render '" + file.string() +
                                   "' --size 8x8 -o out.png", root);
        CHECK(code == 1);
        CHECK_FALSE(fs::exists(elsewhere / "out.png"));
    }
    SECTION("extras.teximage and extras.textures outside the folder are refused as the scene loads") {
        s["materials"][0]["extras"] = {{"shader", "single_texture"}, {"teximage", "../../../../../../../../etc/passwd"}};
        const fs::path file = save(dir, s);
        CHECK_THAT(load_error(file), Catch::Contains("extras.teximage") && Catch::Contains("leads outside"));
        json named = s;
        named["materials"][0]["extras"] = {{"shader", "single_texture"}, {"textures", {{"u", {{"image", "/etc/passwd"}}}}}};
        CHECK_THAT(load_error(save(dir, named, "named.gltf")), Catch::Contains("extras.textures.u.image") &&
                                                                   Catch::Contains("absolute path"));
        auto [code, err] = run(kQuadshade + " render '" + file.string() + "' --size 8x8 -o " + (root / "o.png").string() +
                                   " --allow-outside-paths", root);
        CHECK(code == 1);  // allowed, read, and not an image
        CHECK_THAT(err, Catch::Contains("/etc/passwd") && Catch::Contains("unsupported image format"));
    }
}

TEST_CASE("textures: only regular files, their size checked on the header before decoding", "[hostile][textures]") {
    const auto dir = temp_dir("hostile-textures");
    json s = triangle_scene();
    s["materials"][0]["extras"] = {{"shader", "single_texture"}, {"teximage", "t.png"}};
    const fs::path file = save(dir, s);
    SECTION("a FIFO is refused without waiting on it") {
        REQUIRE(::mkfifo((dir / "t.png").c_str(), 0600) == 0);
        CHECK_THAT(render_error(file), Catch::Contains("t.png") && Catch::Contains("not a regular file"));
    }
    SECTION("a device such as /dev/zero") {
        fs::create_symlink("/dev/zero", dir / "t.png");
        SceneLoadOptions allow;
        allow.paths.allow_outside = true;
        Scene loaded = load_scene(file, allow);
        FrameRequest r;
        r.width = r.height = 8;
        CHECK_THROWS_WITH(render_frame(loaded, r), Catch::Contains("/dev/zero") && Catch::Contains("not a regular file"));
    }
    SECTION("a small PNG claiming 16384x16384 texels") {
        write_file(dir / "t.png", png_claiming(16384, 16384, dir));
        CHECK(fs::file_size(dir / "t.png") < 1000);
        CHECK_THAT(render_error(file), Catch::Contains("extras.teximage") && Catch::Contains("16384x16384") &&
                                          Catch::Contains("67108864"));
        // compare refuses it from the header too, against the memory it may use.
        auto [code, err] = run(kQuadshade + " compare " + (dir / "t.png").string() + " " + (dir / "t.png").string() +
                                   " --memory-limit 1G", dir);
        CHECK(code == 1);
        CHECK_THAT(err, Catch::Contains("16384x16384"));
    }
    SECTION("embedded images (a data: URI, a bufferView) pass the same checks") {
        const std::string png = png_claiming(16384, 16384, dir);
        for (const ImageSource::Kind kind : {ImageSource::Kind::DataUri, ImageSource::Kind::BufferView}) {
            Scene scene = load_scene(file);
            scene.textures[0].image = {{}, std::vector<std::uint8_t>(png.begin(), png.end()), "image/png", kind};
            save_scene(scene, dir / "embedded.gltf");
            CHECK_THAT(render_error(dir / "embedded.gltf"),
                       Catch::Contains(kind == ImageSource::Kind::DataUri ? "data: URI image" : "bufferView image") &&
                           Catch::Contains("16384x16384") && Catch::Contains("67108864"));
        }
    }
}

TEST_CASE("image files whose containers claim more than they hold are refused before decoding", "[hostile][textures]") {
    // Inputs the image fuzzer found (fuzz/regressions/image; the first byte picks the format):
    // each made a decoder allocate about a gigabyte before it noticed the file was short.
    auto refusal = [](const char* name, const char* as) {
        const std::string bytes = slurp(kSource / "fuzz/regressions/image" / name);
        try {
            decode_image({reinterpret_cast<const unsigned char*>(bytes.data()) + 1, bytes.size() - 1}, as);
        } catch (const ImageError& e) {
            return std::string(e.what());
        }
        return std::string("(decoded)");
    };
    CHECK_THAT(refusal("png-chunk-claims-805-MB", "t.png"), Catch::Contains("PNG chunk 'tEXt' claims 805306393 bytes"));
    CHECK_THAT(refusal("exr-attribute-claims-1.9-GB", "t.exr"), Catch::Contains("OpenEXR attribute") && Catch::Contains("claims"));
    CHECK_THAT(refusal("bmp-rle-claims-805-MB", "t.bmp"), Catch::Contains("unsupported image format '.bmp'"));
    // A channel list whose entries do not fill its declared size: OpenEXR reads it by its layout,
    // goes on from the wrong place and allocated a 2.2 GB string (14 s) for this 745-byte file.
    CHECK_THAT(refusal("exr-channel-list-misread-claims-2.2-GB", "t.exr"),
               Catch::Contains("OpenEXR attribute") && Catch::Contains("not the layout of its type"));
    // A preview whose width times height times 4 overflowed that check's own arithmetic (UBSan).
    CHECK_THAT(refusal("exr-preview-size-overflows", "t.exr"),
               Catch::Contains("OpenEXR attribute") && Catch::Contains("not the layout of its type"));
    // The checks pass files as written: quadshade's own EXR (the fuzz corpus' seed) decodes.
    CHECK(refusal("../../corpus/image/render.exr", "t.exr") == "(decoded)");
}

TEST_CASE("transforms, cameras and hierarchies that would show nothing are reported", "[hostile][nodes]") {
    const auto dir = temp_dir("hostile-nodes");
    json s = triangle_scene();
    SECTION("a translation too large for float") {
        s["nodes"][0]["translation"] = {1e39, 0, 0};
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("nodes[0].translation") && Catch::Contains("not a finite float"));
    }
    SECTION("an all-zero matrix") {
        s["nodes"][0]["matrix"] = json::array();
        for (int i = 0; i < 16; ++i) s["nodes"][0]["matrix"].push_back(0);
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("nodes[0]") && Catch::Contains("degenerate"));
    }
    SECTION("a zero camera matrix") {
        s["nodes"][1].erase("translation");
        s["nodes"][1]["matrix"] = json::array();
        for (int i = 0; i < 16; ++i) s["nodes"][1]["matrix"].push_back(0);
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("nodes[1]") && Catch::Contains("camera's transform"));
    }
    SECTION("a zero quaternion") {
        s["nodes"][0]["rotation"] = {0, 0, 0, 0};
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("nodes[0].rotation"));
    }
    SECTION("cycles, shared children and deep chains") {
        s["nodes"][0]["children"] = {0};
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("nodes[0]") && Catch::Contains("reached twice"));
        s["nodes"][0].erase("children");
        s["nodes"].push_back({{"children", {0}}});
        s["nodes"].push_back({{"children", {0}}});
        s["scenes"][0]["nodes"] = {2, 3, 1};
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("nodes[0]") && Catch::Contains("reached twice"));
        json chain = triangle_scene();
        for (int i = 0; i < 200; ++i) chain["nodes"].push_back({{"children", {i == 0 ? 0 : 1 + i}}});
        chain["scenes"][0]["nodes"] = {201, 1};
        CHECK_THAT(load_error(save(dir, chain)), Catch::Contains("deeper than 128"));
    }
    SECTION("orthographic cameras with zero or absurd magnification") {
        s["cameras"][0] = {{"type", "orthographic"}, {"orthographic", {{"xmag", 0}, {"ymag", 1}, {"znear", 0}, {"zfar", 10}}}};
        CHECK_THAT(load_error(save(dir, s)), Catch::Contains("cameras[0].orthographic"));
        s["cameras"][0]["orthographic"]["xmag"] = 1e38;
        const fs::path file = save(dir, s);
        CHECK(render_error(file) == "(rendered)");
#if defined(QUADSHADE_HAS_RAYCAST)
        FrameRequest r;
        r.backend = Backend::RayCaster;
        CHECK_THAT(render_error(file, r), Catch::Contains("Embree") && Catch::Contains("1.8e18"));
#endif
    }
    SECTION("a camera 1e19 from the origin") {
        s["nodes"][1]["translation"] = {0, 0, 1e19};
        const fs::path file = save(dir, s);
        CHECK(render_error(file) == "(rendered)");
#if defined(QUADSHADE_HAS_RAYCAST)
        auto [code, err] = run(kQuadshade + " render " + file.string() + " --backend raycast --size 8x8 -o " +
                                   (dir / "o.png").string(), dir);
        CHECK(code == 1);
        CHECK_THAT(err, Catch::Contains("Embree") && Catch::Contains("rasterizer"));
        CHECK_FALSE(fs::exists(dir / "o.png"));
#endif
    }
}

TEST_CASE("limits: sizes, counts and memory are checked before work, naming the field", "[hostile][limits]") {
    const auto dir = temp_dir("hostile-limits");
    json s = triangle_scene();
    s["scenes"][0]["extras"] = {{"size", {40000, 10}}};
    CHECK_THAT(load_error(save(dir, s, "big.gltf")), Catch::Contains("scenes[0].extras.size") && Catch::Contains("1..32768"));
    const fs::path file = save(dir, triangle_scene());
    const std::string base = kQuadshade + " render " + file.string() + " ";
    CHECK(run(base + "--size 40000x10 -o " + (dir / "o.png").string(), dir).first == 2);
    CHECK(run(base + "--frames 0:2000000 -o " + (dir / "o.png").string(), dir).first == 2);
    SECTION("a whole frame that cannot fit, in a format written whole") {
        auto [code, err] = run(base + "--size 32768x32768 --memory-limit 1G -o " + (dir / "o.hdr").string(), dir);
        CHECK(code == 1);
        CHECK_THAT(err, Catch::Contains("needs 32.0 GiB for the whole frame") && Catch::Contains("1.0 GiB available"));
    }
    SECTION("not even one band fits") {
        auto [code, err] = run(base + "--size 32768x32768 --memory-limit 1M -o " + (dir / "o.png").string(), dir);
        CHECK(code == 1);
        CHECK_THAT(err, Catch::Contains("for a band of 64 rows"));
    }
    CHECK(run(base + "--size 8x8 --memory-limit lots -o " + (dir / "o.png").string(), dir).first == 2);
    CHECK_FALSE(fs::exists(dir / "o.png"));
    CHECK_FALSE(fs::exists(dir / "o.hdr"));
}

TEST_CASE("output names: -o is a name, never a printf format", "[hostile][cli]") {
    for (const char* pattern : {"out_%n.png", "out_%s.png", "out_%x.png", "out_%5d.png", "out_%.png", "out_%",
                                "out_%010d.png", "out_%%.png", "out_%-3d.png", "out_%ld.png", "%d%n"}) {
        INFO(pattern);
        CHECK_THROWS_AS(frame_path(pattern, 3), std::invalid_argument);
    }
    CHECK(frame_path("a%%b_%03d.png", 3) == "a%b_003.png");
    CHECK(frame_path("f%d-%09d.exr", 12) == "f12-000000012.exr");
    CHECK(frame_path("dir/plain.png", 3) == "dir/plain_0003.png");
    CHECK(frame_path("plain.png", 123456) == "plain_123456.png");
    // The command line: exit 2 before anything is read or written (a %n handed to printf would crash).
    const auto dir = temp_dir("hostile-format");
    const std::string base = kQuadshade + " render " + kPlane.string() + " --shader dots --size 16x8 --frames 3:3 -o ";
    auto [code, err] = run(base + "'" + (dir / "out_%n.png").string() + "'", dir);
    CHECK(code == 2);
    CHECK_THAT(err, Catch::Contains("-o") && Catch::Contains("%n"));
    CHECK(std::distance(fs::directory_iterator(dir), {}) == 1);  // stderr.txt alone
    CHECK(run(base + "'" + (dir / "a%%b_%03d.png").string() + "'", dir).first == 0);
    CHECK(fs::exists(dir / "a%b_003.png"));
}

TEST_CASE("outputs: never a folder, an input or through a planted link, written whole or not at all", "[hostile][cli][output]") {
    const auto dir = temp_dir("hostile-output");
    // A scene of its own, with a texture, in a scratch folder: outputs aimed at its files.
    for (const char* f : {"table-1.1-plane.gltf", "table-1.1-plane.bin"}) fs::copy_file(kSource / "scenes/assets" / f, dir / f);
    fs::create_directories(dir / "textures");
    fs::copy_file(kSource / "scenes/assets/textures/halftone-source.png", dir / "textures/halftone-source.png");
    const std::string scene = (dir / "table-1.1-plane.gltf").string();
    const std::string base = kQuadshade + " render " + scene + " --shader halftone --size 32x32 ";
    SECTION("a folder") {
        auto [code, err] = run(base + "-o " + dir.string(), dir);
        CHECK(code == 2);
        CHECK_THAT(err, Catch::Contains("is a folder"));
    }
    SECTION("the scene's own files") {
        const std::string texture = slurp(dir / "textures/halftone-source.png");
        for (const std::string target : {"table-1.1-plane.gltf", "textures/halftone-source.png",
                                          "textures/../table-1.1-plane.bin"}) {
            INFO(target);
            auto [code, err] = run(base + "-o " + (dir / target).string(), dir);
            CHECK(code == 2);
            CHECK_THAT(err, Catch::Contains("is an input"));
        }
        CHECK(slurp(dir / "textures/halftone-source.png") == texture);
        auto [code, err] = run(kQuadshade + " compare " + (dir / "textures/halftone-source.png").string() + " " +
                                   (dir / "textures/halftone-source.png").string() + " --heat-map " +
                                   (dir / "textures/halftone-source.png").string(), dir);
        CHECK(code == 2);
    }
    SECTION("a symlink planted where the output goes is replaced, its target untouched") {
        write_file(dir / "victim.txt", "precious");
        fs::create_symlink(dir / "victim.txt", dir / "out.png");
        CHECK(run(base + "-o " + (dir / "out.png").string(), dir).first == 0);
        CHECK(slurp(dir / "victim.txt") == "precious");
        CHECK_FALSE(fs::is_symlink(dir / "out.png"));
        CHECK(read_image(dir / "out.png").width == 32);
    }
    SECTION("a full disk: the write fails, the previous image stays, no temporary is left") {
        const std::string out = (dir / "out.png").string();
        REQUIRE(run(base + "-o " + out, dir).first == 0);
        const std::string previous = slurp(out);
        // ulimit -f: writes past 4 KiB fail (EFBIG) as on a full disk; SIGXFSZ ignored, so the
        // failure comes back as an error, the way ENOSPC does.
        auto [code, err] = run("trap '' XFSZ; ulimit -f 8; " + kQuadshade + " render " + scene +
                                   " --shader halftone --size 256x256 -o " + out, dir);
        CHECK(code == 1);
        CHECK_THAT(err, Catch::Contains("out.png") && Catch::Contains("cannot write"));
        CHECK(slurp(out) == previous);
        CHECK_FALSE(has_temporaries(dir));
    }
    SECTION("new files get the usual permissions") {
        REQUIRE(run("umask 022; " + base + "-o " + (dir / "mode.png").string(), dir).first == 0);
        CHECK((fs::status(dir / "mode.png").permissions() & fs::perms::all) ==
              (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read));
    }
}

TEST_CASE("SIGINT or SIGTERM during a long animation leaves complete frames and no partial file", "[hostile][cli][signals]") {
    for (const int sig : {SIGTERM, SIGINT}) {
        INFO("signal " << sig);
        const auto dir = temp_dir("hostile-signal-" + std::to_string(sig));
        const pid_t pid = ::fork();
        REQUIRE(pid >= 0);
        if (pid == 0) {
            // Long enough to be interrupted (tens of seconds) and short enough that the names of
            // every frame, checked before the first is drawn, take a moment under ASan too.
            const std::string out = (dir / "f_%06d.png").string();
            ::execl(kQuadshade.c_str(), "quadshade", "render", kPlane.c_str(), "--shader", "perlin", "--size", "96x30", "--frames",
                    "0:9999", "-o", out.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        auto frames = [&] {
            int n = 0;
            for (const auto& e : fs::directory_iterator(dir)) n += e.path().extension() == ".png" && e.path().filename().string()[0] == 'f';
            return n;
        };
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
        while (frames() < 5 && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(5));
        ::kill(pid, sig);
        int status = 0;
        ::waitpid(pid, &status, 0);
        CHECK(WIFSIGNALED(status));
        CHECK(WTERMSIG(status) == sig);
        CHECK(frames() >= 5);
        CHECK_FALSE(has_temporaries(dir));
        for (const auto& e : fs::directory_iterator(dir)) {
            INFO(e.path());
            const Image frame = read_image(e.path());
            CHECK(frame.width == 96);
            CHECK(frame.height == 30);
        }
    }
}

}  // namespace qs
