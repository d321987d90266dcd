// `quadshade test` under attack and careless use (docs/reliability.md, "Outputs" and "Golden-image
// suites"): reports aimed at links, devices, goldens and scenes; suites whose cases share files,
// name files outside their folder or nest deep; fragments that lie; memory; signals and full disks.
// Each test performs the attack and checks that every file the command does not own is intact
// and that it ends with exit 0 or a message naming the file and field.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
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

// A suite of `cases` (JSON objects) on the plane at 16x8 unless a case says otherwise.
std::string suite_json(const std::string& cases, const std::string& top = "") {
    return R"({"name": "attacks", "defaults": {"scene": "scenes/table-1.1-plane.gltf", "size": "16x8"})" + top +
           R"(, "cases": [)" + cases + "]}";
}

const std::string kThreeCases =
    R"({"name": "a", "shader": "dots"}, {"name": "b", "shader": "perlin"}, {"name": "c", "shader": "checker"})";

// A folder with the plane and a blessed suite of three cases.
fs::path blessed_suite(const std::string& name) {
    const fs::path dir = plane_folder(name);
    write_file(dir / "suite.json", suite_json(kThreeCases));
    REQUIRE(sh(kQuadshade + " test suite.json --update", dir).code == 0);
    return dir;
}

bool is_kind(const fs::path& p, mode_t kind) {
    struct stat st {};
    return ::lstat(p.c_str(), &st) == 0 && (st.st_mode & S_IFMT) == kind;
}

// A fragment of the format `test --report` writes, one shard of `shards`, with `results`.
std::string fragment_json(const std::string& results, const std::string& shards = "1", const std::string& shard = "1",
                          const std::string& cases = "1") {
    return R"({"format": "quadshade-test-fragment/2", "suite": "attacks", "shard": )" + shard + R"(, "shards": )" +
           shards + R"(, "suite_cases": )" + cases + R"(, "results": [)" + results + "]}";
}

std::string result_json(const std::string& name, const std::string& expected = "", const std::string& index = "0") {
    return R"({"name": ")" + name + R"(", "index": )" + index + R"(, "status": "PASS", "message": "", "pixels": 128,
               "failing": 0, "warning": 0, "max_steps": 0, "seconds": 0.01, "expected": ")" +
           expected + R"(", "actual": "", "diff": ""})";
}

}  // namespace

TEST_CASE("test reports: a link is replaced, a stream is written into, nothing is renamed over a device",
          "[suites][outputs]") {
    const fs::path dir = blessed_suite("suite-report-places");
    SECTION("--junit /dev/stdout: the report on standard output, /dev/stdout still the link it was") {
        const Ran r = sh(kQuadshade + " test suite.json --junit /dev/stdout", dir);
        CHECK(r.code == 0);
        CHECK_THAT(r.out, Contains("<testsuites") && Contains("</testsuites>"));
        CHECK(is_kind("/dev/stdout", S_IFLNK));
    }
    SECTION("--report /dev/null and --junit /dev/stderr: streamed, the devices left as they are") {
        const Ran r = sh(kQuadshade + " test suite.json --report /dev/null --junit /dev/stderr", dir);
        CHECK(r.code == 0);
        CHECK_THAT(r.err, Contains("<testsuites"));
        CHECK(is_kind("/dev/null", S_IFCHR));
    }
    SECTION("a named pipe with a reader gets the report; the pipe stays a pipe") {
        REQUIRE(::mkfifo((dir / "pipe").c_str(), 0600) == 0);
        // Opened for reading first (without waiting for a writer): the report fits in its buffer.
        const int fd = ::open((dir / "pipe").c_str(), O_RDONLY | O_NONBLOCK);
        REQUIRE(fd >= 0);
        CHECK(sh(kQuadshade + " test suite.json --junit pipe", dir).code == 0);
        std::string got(1 << 16, '\0');
        const ssize_t n = ::read(fd, got.data(), got.size());
        ::close(fd);
        CHECK_THAT(got.substr(0, std::size_t(std::max<ssize_t>(n, 0))), Contains("<testsuites"));
        CHECK(is_kind(dir / "pipe", S_IFIFO));
    }
    SECTION("a named pipe nobody reads is reported, not waited on") {
        REQUIRE(::mkfifo((dir / "pipe").c_str(), 0600) == 0);
        const Ran r = sh(kQuadshade + " test suite.json --junit pipe", dir);
        CHECK(r.code == 1);
        CHECK_THAT(r.err, Contains("pipe: a FIFO no process reads"));
    }
    SECTION("a link to another file: the link is replaced, its target untouched") {
        write_file(dir / "victim.txt", "precious");
        fs::create_symlink(dir / "victim.txt", dir / "junit.xml");
        fs::create_symlink(dir / "victim.txt", dir / "fragment.json");
        CHECK(sh(kQuadshade + " test suite.json --junit junit.xml --report fragment.json", dir).code == 0);
        CHECK(slurp(dir / "victim.txt") == "precious");
        CHECK(is_kind(dir / "junit.xml", S_IFREG));
        CHECK_THAT(slurp(dir / "junit.xml"), Contains("<testsuites"));
        CHECK(is_kind(dir / "fragment.json", S_IFREG));
    }
    SECTION("the fixed temporary name of earlier versions, planted as a link, is never opened") {
        write_file(dir / "victim.txt", "precious");
        fs::create_symlink(dir / "victim.txt", dir / ".junit.xml.partial");
        CHECK(sh(kQuadshade + " test suite.json --junit junit.xml", dir).code == 0);
        CHECK(slurp(dir / "victim.txt") == "precious");
        CHECK_THAT(slurp(dir / "junit.xml"), Contains("<testsuites"));
        fs::remove(dir / ".junit.xml.partial");
    }
    SECTION("a folder, or two reports in one file, are refused before the run") {
        fs::create_directories(dir / "folder");
        CHECK(sh(kQuadshade + " test suite.json --junit folder", dir).code == 2);
        const Ran r = sh(kQuadshade + " test suite.json --junit r.xml --report ./r.xml", dir);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Contains("another report of this run"));
        CHECK_FALSE(fs::exists(dir / "r.xml"));
    }
    CHECK_FALSE(has_hidden(dir));
}

TEST_CASE("test: a passing case removes only its own stale images, cases sharing a file are refused",
          "[suites][outputs]") {
    const fs::path dir = plane_folder("suite-shared-files");
    // Cases p, p.actual and p.diff: p's failure images would be the other two cases' goldens.
    write_file(dir / "suite.json",
               suite_json(R"({"name": "p", "shader": "dots"}, {"name": "p.actual", "shader": "perlin"},
                             {"name": "p.diff", "shader": "checker"})"));
    fs::create_directories(dir / "expected");
    for (const char* golden : {"p.png", "p.actual.png", "p.diff.png"}) write_file(dir / "expected" / golden, golden);
    for (const char* update : {"", " --update"}) {
        const Ran r = sh(kQuadshade + " test suite.json" + update, dir);
        CHECK(r.code == 1);
        CHECK_THAT(r.err, Contains("suite.json: cases[1].expected: its expected image") &&
                              Contains("is case 'p''s actual image"));
    }
    for (const char* golden : {"p.png", "p.actual.png", "p.diff.png"})
        CHECK(slurp(dir / "expected" / golden) == golden);
    // Two cases naming one expected image.
    write_file(dir / "suite.json", suite_json(R"({"name": "x", "shader": "dots", "expected": "same.png"},
                                                 {"name": "y", "shader": "perlin", "expected": "same.png"})"));
    CHECK_THAT(sh(kQuadshade + " test suite.json --update", dir).err, Contains("is case 'x''s expected image"));
    CHECK_FALSE(fs::exists(dir / "same.png"));
    // A case's own stale images go when it passes.
    write_file(dir / "suite.json", suite_json(R"({"name": "p", "shader": "dots"})"));
    REQUIRE(sh(kQuadshade + " test suite.json --update", dir).code == 0);
    write_file(dir / "expected/p.actual.png", "stale");
    CHECK(sh(kQuadshade + " test suite.json", dir).code == 0);
    CHECK_FALSE(fs::exists(dir / "expected/p.actual.png"));
}

TEST_CASE("test: no report or golden is written over the suite's inputs", "[suites][outputs]") {
    const fs::path dir = blessed_suite("suite-inputs");
    const std::string golden = slurp(dir / "expected/a.png"), scene = slurp(dir / "scenes/table-1.1-plane.gltf"),
                      texture = slurp(dir / "scenes/textures/halftone-source.png");
    for (const std::string attack :
         {"--junit expected/a.png --report scenes/table-1.1-plane.gltf", "--junit expected/a.png",
          "--report scenes/table-1.1-plane.gltf", "--junit scenes/textures/halftone-source.png",
          "--report scenes/table-1.1-plane.bin", "--junit expected/b.actual.png", "--junit suite.json",
          "--update --junit expected/a.png"}) {
        INFO(attack);
        const Ran r = sh(kQuadshade + " test suite.json " + attack, dir);
        CHECK(r.code == 2);
        CHECK_THAT(r.err, Contains("is an input of this command"));
    }
    // --update with an expected image that is the scene's own texture.
    write_file(dir / "update.json",
               suite_json(R"({"name": "t", "shader": "dots", "expected": "scenes/textures/halftone-source.png"})"));
    const Ran r = sh(kQuadshade + " test update.json --update", dir);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("update.json: cases[0]: its expected image") && Contains("is a file the suite reads"));
    CHECK(slurp(dir / "expected/a.png") == golden);
    CHECK(slurp(dir / "scenes/table-1.1-plane.gltf") == scene);
    CHECK(slurp(dir / "scenes/textures/halftone-source.png") == texture);
    // The fragments given to --merge are inputs too.
    REQUIRE(sh(kQuadshade + " test suite.json --report fragment.json", dir).code == 0);
    const std::string fragment = slurp(dir / "fragment.json");
    CHECK(sh(kQuadshade + " test --merge fragment.json --junit fragment.json", dir).code == 2);
    CHECK(sh(kQuadshade + " test --merge fragment.json --junit expected/a.png", dir).code == 2);
    CHECK(slurp(dir / "fragment.json") == fragment);
    CHECK(slurp(dir / "expected/a.png") == golden);
}

TEST_CASE("test: a suite names files in its own folder only, unless --allow-outside-paths", "[suites][paths]") {
    const fs::path dir = plane_folder("suite-paths");
    fs::create_directories(dir / "suite");
    fs::create_directories(dir / "outside");
    fs::create_symlink(dir / "outside", dir / "suite/leads-out");
    const std::string absolute = (dir / "outside/escaped.png").string();
    for (const auto& [suite, message] : std::vector<std::pair<std::string, std::string>>{
             {suite_json(R"({"name": "a", "expected": ")" + absolute + R"("})"),
              "cases[0].expected: '" + absolute + "' is an absolute path"},
             {suite_json(R"({"name": "a", "expected": "../outside/escaped.png"})"), "leads outside the suite's folder"},
             {suite_json(R"({"name": "a"})", R"(, "expected_dir": "/")"),
              "expected_dir: '//a.png' is an absolute path"},
             {suite_json(R"({"name": "a"})", R"(, "expected_dir": "leads-out")"),
              "expected_dir: 'leads-out/a.png' leads outside"},
             {suite_json(R"({"name": "a", "scene": "../scenes/table-1.1-plane.gltf"})"),
              "cases[0].scene: '../scenes/table-1.1-plane.gltf' leads outside"}}) {
        INFO(suite);
        write_file(dir / "suite/suite.json", suite);
        const Ran r = sh(kQuadshade + " test suite/suite.json --update", dir);
        CHECK(r.code == 1);
        CHECK_THAT(r.err, Contains("suite.json: ") && Contains(message) && Contains("--allow-outside-paths"));
    }
    CHECK(fs::is_empty(dir / "outside"));
    CHECK_FALSE(fs::exists("/a.png"));
    // Allowed: the scene beside the suite's folder.
    write_file(dir / "suite/suite.json",
               suite_json(R"({"name": "a", "shader": "dots", "scene": "../scenes/table-1.1-plane.gltf"})"));
    CHECK(sh(kQuadshade + " test suite/suite.json --update --allow-outside-paths", dir).code == 0);
    CHECK(fs::exists(dir / "suite/expected/a.png"));
}

TEST_CASE("test: a suite nested deep, with control characters or wrapping numbers is refused by name",
          "[suites][hostile]") {
    const fs::path dir = plane_folder("suite-hostile");
    const std::string deep = std::string(150000, '[') + std::string(150000, ']');
    for (const auto& [suite, message] : std::vector<std::pair<std::string, std::string>>{
             {R"({"defaults": {"size": )" + deep + R"(}, "cases": [{"name": "a"}]})", "nested more than 64 levels"},
             {R"({"cases": [{"name": "a", "sise": )" + deep + "}]}", "nested more than 64 levels"},
             {suite_json(R"({"name": "a", "sise": "4x4"})"), "cases[0].sise: unknown field"},
             {suite_json(R"({"name": "a\u0000b"})"), "cases[0].name: 'a?b' holds a control character"},
             {R"({"name": "x\u0000y", "cases": [{"name": "a"}]})", "name: 'x?y' holds a control character"},
             {suite_json(R"({"name": "a", "shader": "dots\u0000"})"),
              "cases[0].shader: 'dots?' holds a control character"},
             {suite_json(R"({"name": "a", "size": "4294967312x8"})"), "cases[0].size: expected WxH within 1..32768"},
             {suite_json(R"({"name": "a", "uniforms": {"u\u0000": 1}})"), "cases[0].uniforms.u?: not the name"}}) {
        INFO(suite.substr(0, 200));
        write_file(dir / "suite.json", suite);
        const Ran r = sh(kQuadshade + " test suite.json", dir);
        CHECK(r.code == 1);
        CHECK_THAT(r.err, Contains("suite.json: ") && Contains(message));
    }
    for (const std::string shard : {"4294967297/4294967298", "1/0", "2/1", "1/100001", "1/2x", "-1/2", "1"}) {
        INFO(shard);
        CHECK(sh(kQuadshade + " test suite.json --shard " + shard, dir).code == 2);
    }
    CHECK(sh(kQuadshade + " test suite.json --memory-limit '8G extra'", dir).code == 2);
}

TEST_CASE("test --merge: lying fragments are refused by file and field, their paths read only inside their folder",
          "[suites][merge]") {
    const fs::path dir = plane_folder("suite-merge");
    fs::create_directories(dir / "results");
    auto merge = [&](const std::string& fragment, const std::string& options = "") {
        write_file(dir / "results/f.json", fragment);
        return sh(kQuadshade + " test --merge results/f.json" + options, dir);
    };
    // Names that would lead the HTML report's copies out of its folder.
    Ran r = merge(fragment_json(result_json("../../escaped", "/etc/hostname")), " --html html");
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("f.json: results[0].name: not a case's name"));
    // Images outside the fragment's folder: not read unless allowed.
    for (const std::string image : {"/etc/hostname", "../scenes/textures/halftone-source.png"}) {
        r = merge(fragment_json(result_json("a", image)), " --html html");
        CHECK(r.code == 1);
        CHECK_THAT(r.err, Contains("results[0].expected: '" + image + "'") && Contains("--allow-outside-paths"));
    }
    CHECK_FALSE(fs::exists(dir / "html/images"));
    // The JUnit report alone reads no image: the paths are only text there.
    CHECK(merge(fragment_json(result_json("a", "../scenes/textures/halftone-source.png")), " --junit j.xml").code == 0);
    // Numbers and names that lie.
    for (const auto& [fragment, message] : std::vector<std::pair<std::string, std::string>>{
             {fragment_json(result_json("a"), "100000000"), "shards: expected a whole number within 1..100000"},
             {fragment_json(result_json("a"), "3", "2.9"), "shard: expected a whole number"},
             {fragment_json(result_json("a"), "3", "0"), "shard: expected a whole number within 1..3"},
             {fragment_json(result_json("a"), "4294967298", "4294967297"), "shards: expected a whole number within"},
             {fragment_json(result_json("a") + "," + result_json("a", "", "1"), "1", "1", "2"),
              "'a' is an earlier result's name"},
             {fragment_json(result_json("a\\u0000b")), "results[0].name: holds a control character"},
             {fragment_json(result_json("a", "", "5")), "results[0].index: expected a whole number within 0..0"},
             {fragment_json(result_json("a"), "1", "1", "1000000000"),
              "suite_cases: expected a whole number within 1..1000000"},
             {std::string(100000, '[') + std::string(100000, ']'), "nested more than 64 levels"}}) {
        INFO(fragment.substr(0, 200));
        r = merge(fragment);
        CHECK(r.code == 1);
        CHECK_THAT(r.err, Contains("f.json") && Contains(message));
        CHECK(r.err.size() < 2000);
    }
    // A fragment of 100,000 shards: the missing ones are counted, not listed.
    r = merge(fragment_json(result_json("a"), "100000"));
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("lack shard 2, 3, 4, 5, 6, 7, 8, 9, 10, 11 and 99989 more of 100000"));
    CHECK(r.err.size() < 2000);
    // The same case in two shards' fragments.
    write_file(dir / "results/g.json", fragment_json(result_json("a", "", "1"), "2", "2", "2"));
    write_file(dir / "results/f.json", fragment_json(result_json("a"), "2", "1", "2"));
    r = sh(kQuadshade + " test --merge results/f.json results/g.json", dir);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("g.json: case 'a' is also in results/f.json"));
}

TEST_CASE("test --merge --html: images inside the fragments' folder are copied, a link in images/ is replaced",
          "[suites][merge]") {
    const fs::path dir = plane_folder("suite-merge-html");
    fs::create_directories(dir / "run");
    write_file(dir / "run/suite.json",
               R"({"name": "m", "defaults": {"scene": "../scenes/table-1.1-plane.gltf", "size": "16x8"},
        "cases": [{"name": "a", "shader": "dots"}, {"name": "b", "shader": "perlin"}]})");
    REQUIRE(sh(kQuadshade + " test run/suite.json --update --allow-outside-paths", dir).code == 0);
    for (const char* k : {"1", "2"}) {
        REQUIRE(sh(kQuadshade + " test run/suite.json --allow-outside-paths --shard " + std::string(k) +
                       "/2 --report run/shard" + k + ".json",
                   dir)
                    .code == 0);
    }
    // A link planted where the page's image goes, and one to the victim as the images folder.
    write_file(dir / "victim.png", "precious");
    fs::create_directories(dir / "html/images");
    fs::create_symlink(dir / "victim.png", dir / "html/images/a.expected.png");
    CHECK(sh(kQuadshade + " test --merge run/shard1.json run/shard2.json --html html", dir).code == 0);
    CHECK(slurp(dir / "victim.png") == "precious");
    CHECK(is_kind(dir / "html/images/a.expected.png", S_IFREG));
    CHECK(slurp(dir / "html/images/a.expected.png") == slurp(dir / "run/expected/a.png"));
    fs::create_directories(dir / "elsewhere");
    fs::create_directories(dir / "html2");
    fs::create_symlink(dir / "elsewhere", dir / "html2/images");
    const Ran r = sh(kQuadshade + " test --merge run/shard1.json run/shard2.json --html html2", dir);
    CHECK(r.code == 1);
    CHECK_THAT(r.err, Contains("html2/images: is a symbolic link"));
    CHECK(fs::is_empty(dir / "elsewhere"));
    CHECK_FALSE(has_hidden(dir));
}

TEST_CASE("test: memory is planned per case (bands, a shared budget, sizes read from headers)", "[suites][memory]") {
    const fs::path dir = plane_folder("suite-memory");
    // A case too large for the limit fails with the size it needs; the others run.
    write_file(dir / "suite.json", suite_json(R"({"name": "huge", "shader": "dots", "size": "32768x32768"},
                                                 {"name": "small", "shader": "dots"})"));
    Ran r = sh(kQuadshade + " test suite.json --update --memory-limit 1G", dir);
    CHECK(r.code == 3);
    CHECK_THAT(r.out, Contains("FAIL    huge") && Contains("needs") &&
                          Contains("more than the 1.0 GiB available (--memory-limit sets it)"));
    CHECK_THAT(r.out, Contains("UPDATED small"));
    CHECK_FALSE(fs::exists(dir / "expected/huge.png"));
    // Two cases that fit the budget one at a time, run with --jobs 2: they take turns.
    write_file(dir / "suite.json", suite_json(R"({"name": "a", "shader": "dots", "size": "512x512"},
                                                 {"name": "b", "shader": "perlin", "size": "512x512"})"));
    REQUIRE(sh(kQuadshade + " test suite.json --update", dir).code == 0);
    r = sh(kQuadshade + " test suite.json --jobs 2 --memory-limit 30M", dir);
    CHECK(r.code == 0);
    CHECK_THAT(r.out, Contains("2 cases, 2 passed"));
    // An expected image whose header claims 16384x16384 (a 1-pixel PNG with a forged header) is
    // refused on its header, before anything is decoded.
    write_image(dir / "one.png", Image{1, 1, {0.5f, 0.5f, 0.5f, 1.0f}});
    std::string png = slurp(dir / "one.png");
    auto put32 = [&](std::size_t at, std::uint32_t v) {
        for (int i = 0; i < 4; ++i) png[at + std::size_t(i)] = char(v >> (24 - 8 * i));
    };
    put32(16, 16384), put32(20, 16384);
    std::uint32_t crc = 0xFFFFFFFFu;  // the IHDR chunk's CRC-32, over bytes 12..28
    for (std::size_t i = 12; i < 29; ++i) {
        crc ^= std::uint8_t(png[i]);
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    put32(29, ~crc);
    write_file(dir / "expected/a.png", png);
    r = sh(kQuadshade + " test suite.json --memory-limit 200M", dir);
    CHECK(r.code == 3);
    CHECK_THAT(r.out, Contains("FAIL    a") && Contains("image is 16384x16384, not the 512x512 it is compared with"));
}

TEST_CASE("test: a full disk, a file size limit and two runs on one report leave whole files and no temporary",
          "[suites][outputs]") {
    const fs::path dir = plane_folder("suite-disk");
    std::string cases;
    for (int i = 0; i < 10; ++i)
        cases += (i ? ", " : "") + std::string(R"({"name": "case-)") + std::to_string(i) + R"(", "shader": "dots"})";
    write_file(dir / "suite.json", suite_json(cases));
    REQUIRE(sh(kQuadshade + " test suite.json --update", dir).code == 0);
    REQUIRE(sh(kQuadshade + " test suite.json --junit junit.xml --report fragment.json", dir).code == 0);
    const std::string junit = slurp(dir / "junit.xml"), fragment = slurp(dir / "fragment.json");
    REQUIRE(junit.size() > 512);
    REQUIRE(fragment.size() > 512);
    // ulimit -f 1: writes past 512 bytes fail. SIGXFSZ is not ignored here, as a user's shell leaves it.
    for (const char* report : {"--junit junit.xml", "--report fragment.json"}) {
        INFO(report);
        const Ran r = sh("ulimit -f 1; " + kQuadshade + " test suite.json " + report, dir);
        CHECK(r.code == 1);
        CHECK_THAT(r.err, Contains("cannot write: File too large"));
    }
    CHECK(slurp(dir / "junit.xml") == junit);
    CHECK(slurp(dir / "fragment.json") == fragment);
    CHECK_FALSE(has_hidden(dir));
    // Two runs writing one report at once, three times over: both succeed, the report is whole.
    for (int round = 0; round < 3; ++round) {
        const std::string run = kQuadshade + " test suite.json --junit same.xml --report same.json > /dev/null 2>&1";
        const Ran r =
            sh("(" + run + " & p=$!; " + run + " & q=$!; wait $p; a=$?; wait $q; b=$?; exit $((a + b)))", dir);
        CHECK(r.code == 0);
        const std::string same = slurp(dir / "same.xml");
        CHECK(same.rfind("<?xml", 0) == 0);
        CHECK_THAT(same, Contains("case-9") && Contains("</testsuites>"));
        CHECK_THAT(slurp(dir / "same.json"), Contains("quadshade-test-fragment"));
    }
    CHECK_FALSE(has_hidden(dir));
}

TEST_CASE("test --update: SIGINT with many cases at once leaves complete goldens and no temporary",
          "[suites][signals]") {
    const fs::path dir = plane_folder("suite-signal");
    std::string cases;
    for (int i = 0; i < 400; ++i)
        cases += (i ? ", " : "") + std::string(R"({"name": "c)") + std::to_string(i) +
                 R"(", "shader": "perlin", "size": "96x64"})";
    write_file(dir / "suite.json", suite_json(cases));
    const pid_t pid = ::fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
        if (::chdir(dir.c_str()) != 0) ::_exit(127);
        const int null = ::open("/dev/null", O_WRONLY);
        ::dup2(null, 1);
        ::execl(kQuadshade.c_str(), "quadshade", "test", "suite.json", "--update", "--jobs", "32",
                static_cast<char*>(nullptr));
        ::_exit(127);
    }
    // The signal once the first golden is written: hundreds of cases are still rendering or writing.
    auto blessed = [&] {
        std::error_code ec;
        for (const auto& e : fs::directory_iterator(dir / "expected", ec)) {
            if (e.path().extension() == ".png" && e.path().filename().string()[0] != '.') return true;
        }
        return false;
    };
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!blessed() && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    ::kill(pid, SIGINT);
    int status = 0;
    ::waitpid(pid, &status, 0);
    CHECK(WIFSIGNALED(status));
    CHECK_FALSE(has_hidden(dir));
    for (const auto& e : fs::directory_iterator(dir / "expected")) {
        INFO(e.path());
        CHECK(read_image(e.path()).width == 96);
    }
}

TEST_CASE("test --update in the suite's own folder, expected images beside it", "[suites]") {
    const fs::path dir = plane_folder("suite-own-folder");
    write_file(dir / "suite.json", suite_json(R"({"name": "a", "shader": "dots", "expected": "a.png"})"));
    const Ran r = sh(kQuadshade + " test suite.json --update", dir);
    CHECK(r.code == 0);
    CHECK(read_image(dir / "a.png").width == 16);
}

}  // namespace qs
