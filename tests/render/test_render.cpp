// render/: a frame rendered in row bands is the whole frame bit for bit, on both backends;
// thread counts and runs change no bit; memory is planned before it is allocated; a long
// animation holds its resident memory flat.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <thread>

#include "images/image_io.h"
#include "render/gallery.h"
#include "render/memory_plan.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "shading/catalogue.h"
#include "tests/test_paths.h"

namespace qs {

namespace {

using namespace test;

std::vector<Backend> backends() {
#if defined(QUADSHADE_HAS_RAYCAST)
    return {Backend::Rasterizer, Backend::RayCaster};
#else
    return {Backend::Rasterizer};
#endif
}

const char* name(Backend b) { return b == Backend::Rasterizer ? "raster" : "raycast"; }

bool same_bits(const void* a, const void* b, std::size_t bytes) { return std::memcmp(a, b, bytes) == 0; }

}  // namespace

TEST_CASE("row bands: every band holds exactly the whole frame's pixels, on both backends", "[render][bands]") {
    Scene figure = load_scene(kFigure), plane = load_scene(kPlane);
    struct Case {
        Scene* scene;
        const char* shader;
        int width, height;
    };
    // Odd heights put the bottom-up quad grid at row -1; the halftone and Worley tiles take
    // derivatives (helper rows across band edges would show), Figure 1.1's spheres overlap under
    // the depth test. (Table 1.1's shaders: sanitizer builds compile them too.)
    const Case cases[] = {{&figure, "worley_tiles", 201, 137}, {&plane, "halftone", 130, 193}, {&plane, "dots", 64, 64}};
    for (const Case& c : cases) {
        for (Backend backend : backends()) {
            for (QuadPairing pairing : {QuadPairing::TopDown, QuadPairing::BottomUp}) {
                FrameRequest r;
                r.width = c.width, r.height = c.height;
                r.shader_override = c.shader;
                r.backend = backend;
                r.shading.pairing = pairing;
                r.shading.check_undefined = true;
                SceneRenderer renderer(*c.scene, r);
                Framebuffer whole, band;
                renderer.render_into(whole, 0.25);
                REQUIRE(whole.rows == c.height);
                for (int rows : {64, 128}) {
                    const std::vector<RowBand> bands = image_bands(c.height, pairing, rows);
                    CHECK(bands.front().begin == 0);
                    CHECK(bands.back().end == c.height);
                    for (const RowBand& b : bands) {
                        INFO(c.shader << " " << name(backend) << " pairing " << int(pairing) << " rows " << rows << " band "
                                      << b.begin << ".." << b.end);
                        renderer.render_into(band, 0.25, nullptr, b);
                        REQUIRE(band.first_row == b.begin);
                        REQUIRE(band.rows == b.end - b.begin);
                        CHECK(same_bits(band.rgba.data(), whole.pixel(0, b.begin), band.rgba.size() * sizeof(float)));
                        CHECK(same_bits(band.undefined.data(), &whole.undefined[whole.index(0, b.begin)], band.undefined.size()));
                    }
                }
                // A band that cuts a tile would change pixels: refused.
                CHECK_THROWS_AS(renderer.render_into(band, 0.25, nullptr, RowBand{10, 20}), std::invalid_argument);
            }
        }
    }
}

TEST_CASE("images are bit-identical for 1, 2 and 7 threads and across runs, on both backends", "[render][determinism]") {
    Scene figure = load_scene(kFigure), plane = load_scene(kPlane);
    for (Backend backend : backends()) {
        for (Scene* scene : {&figure, &plane}) {
            FrameRequest r;
            r.width = 316, r.height = 100;
            r.backend = backend;
            r.shader_override = scene == &plane ? "worley_tiles" : "perlin";
            std::vector<Framebuffer> frames;
            for (int threads : {1, 2, 7, 7, 1}) {
                r.shading.threads = threads;
                frames.push_back(render_frame(*scene, r));
            }
            for (std::size_t i = 1; i < frames.size(); ++i) {
                INFO(name(backend) << " run " << i);
                CHECK(same_bits(frames[0].rgba.data(), frames[i].rgba.data(), frames[0].rgba.size() * sizeof(float)));
            }
        }
        // Across processes: two runs of the command line, seven threads, float output.
        const auto dir = temp_dir(std::string("determinism-") + name(backend));
        for (const char* out : {"a.exr", "b.exr"}) {
            const std::string cmd = (kBin / "quadshade").string() + " render " + kFigure.string() +
                                    " --shader perlin --size 316x100 --threads 7 --backend " + name(backend) + " -o " + (dir / out).string() +
                                    " 2> /dev/null";
            REQUIRE(std::system(cmd.c_str()) == 0);
        }
        CHECK(read_image(dir / "a.exr").rgba == read_image(dir / "b.exr").rgba);
    }
}

TEST_CASE("the summary line says whether the frame was depth tested, in one band or several", "[render][bands]") {
    const auto dir = temp_dir("summary-depth");
    auto summary = [&](const std::string& scene, const std::string& extra) {
        const std::string cmd = (kBin / "quadshade").string() + " render " + scene + extra + " -o " +
                                (dir / "x.png").string() + " 2> " + (dir / "err.txt").string();
        REQUIRE(std::system(cmd.c_str()) == 0);
        std::ifstream in(dir / "err.txt");
        return std::string((std::istreambuf_iterator<char>(in)), {});
    };
    // The rolled torus hides parts of itself: depth tested, whatever the bands and the shader
    // (constant_color, which the sanitizer builds also compile). Figure 1.1's spheres, their back
    // faces culled, are drawn after the ground behind them: painter's order, no depth buffer.
    const std::string torus = (kSource / "scenes/assets/conformance/torus-rolled.gltf").string();
    CHECK(summary(torus, " --shader constant_color --size 316x100").find(", depth tested") != std::string::npos);
    const std::string banded = summary(torus, " --shader constant_color --size 1264x800 --memory-limit 16M");
    CHECK(banded.find("bands of rows, depth tested") != std::string::npos);
    CHECK(summary(kFigure.string(), " --shader constant_color --size 1264x400").find(", no depth buffer") != std::string::npos);
    CHECK(summary(kPlane.string(), " --size 316x100").find(", no depth buffer") != std::string::npos);
}

TEST_CASE("memory plans: one band when it fits, the fewest bands that fit, or a message with the size", "[render][memory]") {
    MemoryPlanInput in;
    in.height = 1000;
    in.bytes_for_rows = [](int rows) { return std::uint64_t(rows) * 1000 + 5000; };
    in.limit = 10'000'000;
    in.can_band = true;
    CHECK(plan_bands(in).size() == 1);
    in.band_budget = 300'000;  // 295 rows fit: bands of 256
    const std::vector<RowBand> bands = plan_bands(in);
    CHECK(bands.size() == 4);
    for (const RowBand& b : bands) CHECK(in.bytes_for_rows(b.end - b.begin) <= in.band_budget);
    in.limit = 50'000;  // 64 rows need 69 000 bytes
    CHECK_THROWS_WITH(plan_bands(in), Catch::Contains("needs 67.4 KiB for a band of 64 rows") && Catch::Contains("48.8 KiB available"));
    in.can_band = false;
    in.limit = 2'000'000;
    CHECK(plan_bands(in).size() == 1);  // written whole: fits the limit, if not the band budget
    in.limit = 900'000;
    CHECK_THROWS_WITH(plan_bands(in), Catch::Contains("for the whole frame"));
    // What the scene and the renderer hold comes off the limit, and counts in the size needed.
    in.can_band = true;
    in.limit = 10'000'000, in.band_budget = std::uint64_t(1) << 30;
    in.held = 9'700'000;  // 300 000 bytes left: bands of 256 rows
    CHECK(plan_bands(in).size() == 4);
    in.held = 9'960'000;  // 40 000 left, less than a band of 64 rows (69 000)
    CHECK_THROWS_WITH(plan_bands(in), Catch::Contains("needs 9.6 MiB for a band of 64 rows") && Catch::Contains("9.5 MiB available"));

    CHECK(parse_byte_size("512M") == 512ull << 20);
    CHECK(parse_byte_size("1.5GiB") == 3ull << 29);
    CHECK(parse_byte_size("4096") == 4096);
    CHECK(parse_byte_size("2 g") == 2ull << 30);
    CHECK_THROWS(parse_byte_size("lots"));
    CHECK_THROWS(parse_byte_size("-1G"));
    CHECK_THROWS(parse_byte_size("5X"));
    CHECK_THROWS(parse_byte_size("1e30"));
    CHECK(available_memory() > (std::uint64_t(16) << 20));
}

// Sanitizers keep shadow memory and freed blocks: a sanitized render's resident memory is not what
// its plan counts, and the checking builds (tests/CMakeLists.txt defines QUADSHADE_SANITIZED) leave
// this test out.
#ifndef QUADSHADE_SANITIZED

namespace {

// A size as byte_size_text writes it ("12.5 MiB", "512 bytes"), in bytes.
double size_in_bytes(const std::string& text) {
    std::istringstream in(text);
    double v = 0.0;
    std::string unit;
    in >> v >> unit;
    const std::vector<std::string> units = {"bytes", "KiB", "MiB", "GiB"};
    const auto u = std::find(units.begin(), units.end(), unit);
    REQUIRE(u != units.end());
    return v * double(std::uint64_t(1) << (10 * (u - units.begin())));
}

}  // namespace

TEST_CASE("a render's measured peak memory is within its plan, and a banded one within --memory-limit", "[render][memory]") {
    const auto dir = temp_dir("memory-plan");
    // A mipmapped texture of 1024x512 on the conformance plane: the frame, the texture with its
    // mipmaps and its decoding all count.
    const std::filesystem::path conformance = kSource / "scenes/assets/conformance";
    std::filesystem::create_directories(dir / "images");
    for (const char* file : {"texture-min-linear-mipmap-linear.gltf", "texture-min-linear-mipmap-linear.bin"}) {
        std::filesystem::copy_file(conformance / file, dir / file, std::filesystem::copy_options::overwrite_existing);
    }
    const std::string quadshade = (kBin / "quadshade").string();
    auto run = [&](const std::string& args) {
        const std::string cmd = quadshade + " render " + args + " 2> " + (dir / "err.txt").string();
        REQUIRE(std::system(cmd.c_str()) == 0);
        std::ifstream in(dir / "err.txt");
        return std::string((std::istreambuf_iterator<char>(in)), {});
    };
    run(kPlane.string() + " --size 1024x512 -o " + (dir / "images/texture-64x32.png").string());
    const std::string scene = (dir / "texture-min-linear-mipmap-linear.gltf").string();
    static const std::regex memory(R"(peak memory ([0-9.]+ [A-Za-z]+) \(planned ([0-9.]+ [A-Za-z]+)\))");
    auto check = [&](const std::string& args, double limit) {
        const std::string summary = run(args);
        std::smatch m;
        REQUIRE(std::regex_search(summary, m, memory));
        const double measured = size_in_bytes(m[1]), planned = size_in_bytes(m[2]);
        INFO(summary);
        CHECK(measured > 8e6);  // the frame and the texture were measured
        CHECK(planned >= measured);
        CHECK(planned <= 1.5 * measured + 2e6);  // not wildly above
        if (limit > 0) CHECK(planned <= limit);
        return summary;
    };
    for (const Backend b : backends()) {
        const std::string backend = std::string(" --backend ") + name(b);
        check(scene + backend + " --size 1024x768 -o " + (dir / "frame.png").string(), 0);
        check(scene + backend + " --size 1024x768 -o " + (dir / "frame.exr").string(), 0);
        const std::string banded = check(scene + backend + " --size 1024x768 --memory-limit 20M -o " +
                                         (dir / "banded.png").string(), 20 << 20);
        CHECK(banded.find("bands of rows") != std::string::npos);
    }
}

TEST_CASE("a bake's measured peak memory is within its plan, and one over --memory-limit is refused with nothing written",
          "[render][memory][bake]") {
    const auto dir = temp_dir("bake-memory-plan");
    const std::string bake = (kBin / "quadshade").string() + " bake " +
                             (kSource / "scenes/assets/bake/atlas-sphere.gltf").string() + " --shader noise_bumps";
    auto run = [&](const std::string& args) {
        const std::string cmd = bake + " " + args + " 2> " + (dir / "err.txt").string();
        const int status = std::system(cmd.c_str());
        std::ifstream in(dir / "err.txt");
        return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                              std::string((std::istreambuf_iterator<char>(in)), {}));
    };
    static const std::regex memory(R"(peak memory ([0-9.]+ [A-Za-z]+) \(planned ([0-9.]+ [A-Za-z]+)\))");
    for (const char* maps : {"color", "color,height,normal"}) {
        const auto [status, summary] = run(std::string("--size 512 --skirt 1 --maps ") + maps + " -o " +
                                           (dir / "baked.gltf").string());
        INFO(summary);
        REQUIRE(status == 0);
        std::smatch m;
        REQUIRE(std::regex_search(summary, m, memory));
        const double measured = size_in_bytes(m[1]), planned = size_in_bytes(m[2]);
        CHECK(measured > 4e6);  // the atlas was measured
        CHECK(planned >= measured);
        // Not wildly above: the colour atlas's measured peak moves between runs (9.1 to 9.4 MiB
        // for a plan of 15.6 MiB), with the pages its allocations happen to reuse.
        CHECK(planned <= 2.0 * measured + 2e6);
    }
    const auto [status, message] = run("--size 512 --memory-limit 4M -o " + (dir / "refused.gltf").string());
    CHECK(status == 1);
    CHECK(message.find("bake: the colour atlas at 512x512 needs") != std::string::npos);
    CHECK(message.find("more than the 4.0 MiB available") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir / "refused.gltf"));
    CHECK_FALSE(std::filesystem::exists(dir / "refused-color.png"));
}

#endif

TEST_CASE("a 2000-frame animation holds its resident memory flat", "[render][soak]") {
    // Frames go to /dev/shm where there is one (fsync there costs nothing), else a scratch folder.
    const std::filesystem::path shm = "/dev/shm";
    const auto dir = std::filesystem::is_directory(shm) && ::access(shm.c_str(), W_OK) == 0
                         ? shm / ("quadshade-soak-" + std::to_string(::getpid()))
                         : temp_dir("soak");
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string quadshade = (kBin / "quadshade").string(), out = (dir / "f_%04d.png").string();
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        ::execl(quadshade.c_str(), "quadshade", "render", kPlane.c_str(), "--shader", "flow_noise", "--size", "32x32",
                "--frames", "0:1999", "-o", out.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // Resident anonymous memory (kB: the heap, stacks; not the libraries' pages, which the kernel
    // maps in and out as it likes) sampled every 2 ms, with the number of frames written by then.
    std::vector<std::pair<long, long>> samples;
    const std::string status = "/proc/" + std::to_string(pid) + "/status";
    int wstatus = 0;
    while (::waitpid(pid, &wstatus, WNOHANG) == 0) {
        std::ifstream in(status);
        std::string line;
        while (std::getline(in, line)) {
            if (line.rfind("RssAnon:", 0) == 0) {
                long frames = 0;
                for (auto it = std::filesystem::directory_iterator(dir); it != std::filesystem::directory_iterator(); ++it) ++frames;
                samples.emplace_back(frames, std::stol(line.substr(8)));
            }
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    std::filesystem::remove_all(dir);
    REQUIRE(WIFEXITED(wstatus));
    REQUIRE(WEXITSTATUS(wstatus) == 0);
    // Frames 200..600 against frames 1000..2000: the first frames warm up (thread pool, caches).
    long early = 0, late = 0;
    std::size_t late_samples = 0;
    for (const auto& [frames, rss] : samples) {
        if (frames >= 200 && frames < 600) early = std::max(early, rss);
        if (frames >= 1000) late = std::max(late, rss), ++late_samples;
    }
    std::printf("2000-frame animation (plane, flow_noise, 32x32, PNG per frame): %zu samples, resident anonymous "
                "memory %ld kB at frames 200-600, %ld kB at 1000-2000\n", samples.size(), early, late);
    REQUIRE(late_samples > 10);
    REQUIRE(early > 0);
    CHECK(late - early <= 1024);  // a leak of 1 kB per frame would show as 1000 kB
}

TEST_CASE("a shader that declares no time draws the same image at every time, so an animation of such shaders renders once", "[render][time]") {
    // The declaration is what lets the renderer reuse a frame: held for every catalogue shader
    // this build has, on its plane (shaders whose samplers the plane does not bind are left out).
    int checked = 0;
    for (const Program* p : catalogue()) {
        const ShaderInfo& info = p->info();
        if (info.needs.time) continue;
        Scene scene = load_scene(plane_for(info.name));
        FrameRequest r;
        r.width = r.height = 40;
        r.shader_override = std::string(info.name);
        std::vector<Framebuffer> frames;
        try {
            for (const double t : {0.0, 3.7, 1234.5}) {
                r.time = t;
                frames.push_back(render_frame(scene, r));
            }
        } catch (const SceneError&) {
            continue;  // a sampler the plane does not bind
        }
        INFO(info.name);  // bits: the probes' NaN are no equal floats
        const std::size_t bytes = frames[0].rgba.size() * sizeof(float);
        CHECK(same_bits(frames[0].rgba.data(), frames[1].rgba.data(), bytes));
        CHECK(same_bits(frames[0].rgba.data(), frames[2].rgba.data(), bytes));
        ++checked;
    }
    CHECK(checked >= 3);

    const auto dir = temp_dir("render-once");
    auto run = [&](const std::string& shader, const std::string& pattern) {
        const std::string cmd = (kBin / "quadshade").string() + " render " + kPlane.string() + " --shader " + shader +
                                " --size 48x32 --frames 0:3 -o " + (dir / pattern).string() + " 2> " + (dir / "err.txt").string();
        REQUIRE(std::system(cmd.c_str()) == 0);
        std::ifstream in(dir / "err.txt");
        return std::string((std::istreambuf_iterator<char>(in)), {});
    };
    CHECK(run("constant_color", "still_%d.png").find("4 frames 48x32") != std::string::npos);
    CHECK(run("constant_color", "still_%d.png").find("rendered once") != std::string::npos);
    for (int f = 1; f <= 3; ++f) {
        CHECK(read_image(dir / ("still_" + std::to_string(f) + ".png")).rgba == read_image(dir / "still_0.png").rgba);
    }
    // flow_noise reads time: every frame is rendered.
    if (find_program("flow_noise")) CHECK(run("flow_noise", "moving_%d.png").find("rendered once") == std::string::npos);
}


TEST_CASE("a shader reading texture coordinates on a mesh without TEXCOORD_0 draws as GL does, with a warning",
          "[render][coordinates]") {
    // The Table 1.1 plane without its TEXCOORD_0 attribute.
    const auto dir = temp_dir("no-texcoords");
    std::ifstream in(kPlane);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const std::string attributes = "\"POSITION\": 0,\n            \"TEXCOORD_0\": 1";
    REQUIRE(text.find(attributes) != std::string::npos);
    text.replace(text.find(attributes), attributes.size(), "\"POSITION\": 0");
    std::ofstream(dir / "plane.gltf") << text;
    std::filesystem::copy_file(kPlane.parent_path() / "table-1.1-plane.bin", dir / "table-1.1-plane.bin");
    std::filesystem::copy(kPlane.parent_path() / "textures", dir / "textures", std::filesystem::copy_options::recursive);

    Scene with = load_scene(kPlane), without = load_scene(dir / "plane.gltf");
    CHECK(with.meshes[0].has_texcoords);
    CHECK_FALSE(without.meshes[0].has_texcoords);
    FrameRequest r;
    r.width = r.height = 16;
    r.shader_override = "dots";  // reads st
    CHECK(SceneRenderer(with, r).notes().empty());
    const SceneRenderer dots(without, r);
    REQUIRE(dots.notes().size() == 1);
    CHECK(dots.notes()[0].find("TEXCOORD_0 missing on 1 primitive of 1 mesh drawn by shaders that read it ('dots')") !=
          std::string::npos);
    r.shader_override = "position_derivative_probe";  // reads the object position
    CHECK(SceneRenderer(without, r).notes().empty());

    // The command line renders it (st = (0, 0) everywhere, as in GL) and says why it looks so.
    const std::string cmd = (kBin / "quadshade").string() + " render " + (dir / "plane.gltf").string() +
                            " --shader dots --size 16x16 -o " + (dir / "dots.png").string() + " 2> " + (dir / "err.txt").string();
    REQUIRE(std::system(cmd.c_str()) == 0);
    std::ifstream err(dir / "err.txt");
    const std::string message((std::istreambuf_iterator<char>(err)), {});
    CHECK(message.find("quadshade: warning: ") != std::string::npos);
    CHECK(message.find("plane.gltf: TEXCOORD_0 missing") != std::string::npos);
}


TEST_CASE("the gallery draws every catalogue shader, by collection, each square the shader's own frame", "[render][gallery]") {
    GalleryRequest request;
    request.scenes = {kPlane, kLawlorPlane, kSource / "scenes/assets/solids.gltf"};
    request.tile = 24, request.columns = 4;
    const std::vector<GallerySheet> sheets = render_gallery(request);
    const auto groups = catalogue_by_collection();
    REQUIRE(sheets.size() == groups.size());
    std::size_t shaders = 0;
    for (std::size_t i = 0; i < sheets.size(); ++i) {
        const GallerySheet& sheet = sheets[i];
        INFO(sheet.collection);
        CHECK(sheet.collection == groups[i].first);
        REQUIRE(sheet.drawn.size() == groups[i].second.size());
        shaders += sheet.drawn.size();
        const int n = int(sheet.drawn.size()), columns = std::min(4, n), rows = (n + columns - 1) / columns;
        CHECK(sheet.image.width == columns * 24);
        const int strip = (sheet.image.height - 30) / rows - 24;
        CHECK(sheet.image.height == 30 + rows * (24 + strip));
        // The first shader drawn: its square holds its frame on its scene, pixel for pixel.
        for (int k = 0; k < n; ++k) {
            const auto& [name, scene_file] = sheet.drawn[std::size_t(k)];
            if (scene_file.empty()) continue;
            if (find_program(name)->info().needs.coordinates == Coordinates::Object3D) {
                CHECK(scene_file.filename() == "solids.gltf");
            }
            Scene scene = load_scene(scene_file);
            FrameRequest r = request.frame;
            r.width = r.height = 24;
            r.shader_override = name;
            const Framebuffer fb = render_frame(scene, r);
            const int x0 = (k % columns) * 24, y0 = 30 + (k / columns) * (24 + strip);
            int same = 0;
            for (int y = 0; y < 24; ++y) {
                for (int x = 0; x < 24; ++x) {
                    const float* a = &sheet.image.rgba[(std::size_t(y0 + y) * std::size_t(sheet.image.width) + std::size_t(x0 + x)) * 4];
                    const float* b = &fb.rgba[(std::size_t(y) * 24 + std::size_t(x)) * 4];
                    same += std::memcmp(a, b, 3 * sizeof(float)) == 0;
                }
            }
            CHECK(same == 24 * 24);
            break;
        }
    }
    CHECK(shaders == catalogue().size());
    CHECK(gallery_file_stem("Noise is Beautiful: hashes, Perlin and simplex noise") == "noise-is-beautiful");
    CHECK(gallery_file_stem("libmy_shaders.so") == "libmy-shaders-so");
    CHECK(gallery_file_stem("../../etc/passwd") == "etc-passwd");

    // The command line writes one PNG per collection into the folder, and refuses a file for it.
    const auto dir = temp_dir("gallery");
    const std::string cmd = (kBin / "quadshade").string() + " gallery " + (dir / "sheets").string() +
                            " --size 16 --scenes " + kPlane.string() + " > " + (dir / "out.txt").string();
    REQUIRE(std::system(cmd.c_str()) == 0);
    for (const auto& [collection, programs] : groups) CHECK(std::filesystem::exists(dir / "sheets" / (gallery_file_stem(collection) + ".png")));
    std::ofstream(dir / "a-file") << "x";
    CHECK(std::system(((kBin / "quadshade").string() + " gallery " + (dir / "a-file").string() + " 2>/dev/null").c_str()) != 0);
}

}  // namespace qs
