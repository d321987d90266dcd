// render, bake and shaders --export-glsl under attack and careless use (docs/reliability.md,
// "Outputs"): an undefined-case mask named like the frames, bakes too large for memory or
// interrupted, a missing output folder, a plugin whose shader is named like a path, numbers that
// overflow a float or carry junk, a file size limit. Each test performs the attack and checks that
// every file the command does not own is intact and that it ends with exit 0 or a named error.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "images/image_io.h"
#include "tests/apps/command_tests.h"

namespace qs {

namespace {

using namespace test;
namespace fs = std::filesystem;
using Catch::Contains;

const fs::path kAtlasSphere = kSource / "scenes/assets/bake/atlas-sphere.gltf";

std::size_t entries(const fs::path& dir) { return std::size_t(std::distance(fs::directory_iterator(dir), {})); }

}  // namespace

TEST_CASE("render: an undefined-case mask never overwrites a frame, whatever the patterns' spelling",
          "[render][outputs]") {
    const fs::path dir = plane_folder("render-mask-frames");
    fs::create_directories(dir / "out");
    const std::string render =
        kQuadshade + " render scenes/table-1.1-plane.gltf --shader dots --size 16x8 --frames 0:3 ";
    for (const std::string attack : {"-o f.png --undefined-mask 'f_%04d.png'", "-o 'f_%04d.png' --undefined-mask f.png",
                                     "-o out/f.png --undefined-mask './out/../out/f_%04d.png'",
                                     "-o 'out/f_%02d.png' --undefined-mask 'out/f_%d%d.png'"}) {
        INFO(attack);
        const Ran r = sh(render + attack, dir);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Contains("--undefined-mask: frame") && Contains("'s mask would be written over frame"));
    }
    CHECK(entries(dir / "out") == 0);
    CHECK_FALSE(fs::exists(dir / "f_0000.png"));
    CHECK(sh(render + "-o 'f_%04d.png' --undefined-mask 'm_%04d.png'", dir).code == 0);
    CHECK(fs::exists(dir / "f_0003.png"));
    CHECK(fs::exists(dir / "m_0003.png"));
}

TEST_CASE("render: a file size limit (SIGXFSZ) ends in a message, the previous image kept, no temporary",
          "[render][outputs]") {
    const fs::path dir = plane_folder("render-file-size");
    const std::string render = kQuadshade + " render scenes/table-1.1-plane.gltf --shader perlin ";
    REQUIRE(sh(render + "--size 16x16 -o out.png", dir).code == 0);
    const std::string previous = slurp(dir / "out.png");
    // ulimit -f 8: writes past 4 KiB fail; the shell leaves SIGXFSZ's default action (ending the
    // process) as a user's does.
    const Ran r = sh("ulimit -f 8; " + render + "--size 512x512 -o out.png", dir);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("out.png") && Contains("File too large"));
    CHECK(slurp(dir / "out.png") == previous);
    CHECK_FALSE(has_hidden(dir));
}

TEST_CASE("command-line numbers: a uniform beyond float and a memory limit with junk are refused", "[render][cli]") {
    const fs::path dir = plane_folder("render-numbers");
    const std::string render =
        kQuadshade + " render scenes/table-1.1-plane.gltf --shader wave_aa --size 16x8 -o out.png ";
    for (const std::string value : {"1e39", "-1e39", "1,2,3e40", "[3.5e38]"}) {
        INFO(value);
        const Ran r = sh(render + "--uniform 'uFrequency=" + value + "'", dir);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Contains("beyond a float's range"));
    }
    for (const std::string limit : {"8G extra", "8 G B", "1G1"}) {
        INFO(limit);
        CHECK(sh(render + "--memory-limit '" + limit + "'", dir).code == 2);
    }
    CHECK_FALSE(fs::exists(dir / "out.png"));
    CHECK(sh(render + "--memory-limit 1GiB", dir).code == 0);
}

TEST_CASE("bake: memory is checked before any work, a missing folder reported first, nothing left behind",
          "[bake][memory]") {
    const fs::path dir = temp_dir("bake-memory");
    const std::string bake = kQuadshade + " bake " + kAtlasSphere.string() + " --shader noise_bumps ";
    Ran r = sh(bake + "--maps color,height,normal --size 16384 --memory-limit 1G -o out.gltf", dir);
    CHECK(r.code == 1);
    CHECK_THAT(r.err,
               Contains("bake: the colour atlas at 16384x16384 needs") && Contains("more than the 1.0 GiB available"));
    r = sh(bake + "--maps color,normal --size 4096 --memory-limit 400M -o out.gltf", dir);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("bake: the normal map at 4096x4096 needs"));
    r = sh(bake + "--maps color,height,normal --size 16384 -o missing/out.gltf", dir);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("missing/out.gltf: no folder missing to write into"));
    CHECK(sh(bake + "--size 64 --memory-limit 'lots' -o out.gltf", dir).code == 2);
    CHECK(entries(dir) == 0);
    REQUIRE(sh(bake + "--maps color,normal --size 64 --memory-limit 64M -o out.gltf", dir).code == 0);
    CHECK(read_image(dir / "out-normal.png").width == 64);
    CHECK_FALSE(has_hidden(dir));
}

TEST_CASE("bake: SIGINT removes the staging folder, the previous baked scene stays whole", "[bake][signals]") {
    const fs::path dir = temp_dir("bake-signal");
    const std::string bake =
        kQuadshade + " bake " + kAtlasSphere.string() + " --shader noise_bumps --maps color,normal ";
    REQUIRE(sh(bake + "--size 32 -o out.gltf", dir).code == 0);
    const std::string previous = slurp(dir / "out-color.png");
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        const std::string out = (dir / "out.gltf").string();
        ::execl(kQuadshade.c_str(), "quadshade", "bake", kAtlasSphere.c_str(), "--shader", "noise_bumps", "--maps",
                "color,normal", "--size", "2048", "--threads", "1", "-o", out.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // The signal once a map has been staged: the bake is then well under way.
    auto staged = [&] {
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(dir, ec)) {
            if (e.path().filename().string()[0] == '.' && fs::exists(e.path() / "out-color.png", ec)) return true;
        }
        return false;
    };
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (!staged() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ::kill(pid, SIGINT);
    int status = 0;
    ::waitpid(pid, &status, 0);
    CHECK(WIFSIGNALED(status));
    CHECK_FALSE(has_hidden(dir));
    CHECK(slurp(dir / "out-color.png") == previous);
    CHECK(load_scene(dir / "out.gltf").textures.size() == 2);
}

TEST_CASE("shaders --export-glsl: a plugin's shader named like a path is refused, nothing written",
          "[plugins][outputs]") {
    const fs::path dir = temp_dir("export-escaping");
    fs::create_directories(dir / "a/b/glsl");
    const Ran r =
        sh(kQuadshade + " shaders --plugin '" + (kBin.parent_path() / "plugin-tests/libescaping_name.so").string() +
               "' --export-glsl a/b/glsl",
           dir);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("shader '../../escaped': a shader's name is letters, digits and '_'"));
    CHECK(entries(dir / "a/b/glsl") == 0);
    CHECK(entries(dir / "a/b") == 1);
    CHECK(entries(dir / "a") == 1);
    CHECK(entries(dir) == 1);
}

}  // namespace qs
