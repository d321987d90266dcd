#include "apps/golden_suite.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "core/framebuffer.h"
#include "render/frame_image.h"
#include "render/glsl_shaders.h"
#include "scenes/gltf.h"
#include "scenes/image_io.h"

namespace qs {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// ---- the suite file --------------------------------------------------------------------------

struct Reader {
    std::string file;

    [[noreturn]] void fail(const std::string& field, const std::string& what) const {
        throw std::runtime_error(file + ": " + field + ": " + what);
    }
    void only(const json& object, const std::string& field, std::initializer_list<const char*> known) const {
        if (!object.is_object()) fail(field, "expected an object");
        for (const auto& [key, value] : object.items()) {
            if (std::none_of(known.begin(), known.end(), [&](const char* k) { return key == k; })) {
                std::string names;
                for (const char* k : known) names += (names.empty() ? "" : ", ") + std::string(k);
                fail(field + "." + key, "unknown field (known: " + names + ")");
            }
        }
    }
    std::string text(const json& v, const std::string& field) const {
        if (!v.is_string()) fail(field, "expected a string");
        return v.get<std::string>();
    }
    double number(const json& v, const std::string& field, double lo, double hi) const {
        if (!v.is_number()) fail(field, "expected a number");
        const double x = v.get<double>();
        if (!std::isfinite(x) || x < lo || x > hi) fail(field, "expected a number within [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
        return x;
    }
    template <class T>
    T choice(const json& v, const std::string& field, std::initializer_list<std::pair<const char*, T>> choices) const {
        const std::string s = text(v, field);
        std::string names;
        for (const auto& [name, value] : choices) {
            if (s == name) return value;
            names += (names.empty() ? "" : " | ") + std::string(name);
        }
        fail(field, "expected " + names + ", got '" + s + "'");
    }
};

// `defaults` overlaid by a case's own fields (tolerance merged key by key).
json overlay(const json& defaults, const json& c) {
    json merged = defaults.is_object() ? defaults : json::object();
    for (const auto& [key, value] : c.items()) {
        if (key == "tolerance" && value.is_object() && merged.contains("tolerance") && merged["tolerance"].is_object()) {
            for (const auto& [k, v] : value.items()) merged["tolerance"][k] = v;
        } else {
            merged[key] = value;
        }
    }
    return merged;
}

bool valid_name(const std::string& n) {
    return !n.empty() && n.size() <= 200 && n[0] != '.' &&
           std::all_of(n.begin(), n.end(), [](char ch) { return std::isalnum((unsigned char)ch) || ch == '-' || ch == '_' || ch == '.'; });
}

SuiteCase read_case(const Reader& in, const json& c, const std::string& field, const fs::path& folder, const fs::path& expected_dir) {
    in.only(c, field, {"name", "scene", "shader", "glsl", "vert", "size", "time", "derivatives", "backend", "precision", "uniforms", "expected",
                       "tolerance"});
    SuiteCase sc;
    if (!c.contains("name")) in.fail(field + ".name", "missing");
    sc.name = in.text(c["name"], field + ".name");
    if (!valid_name(sc.name)) in.fail(field + ".name", "'" + sc.name + "': letters, digits, '-', '_' and '.' only (it names files)");
    if (!c.contains("scene")) in.fail(field + ".scene", "missing");
    sc.scene = folder / in.text(c["scene"], field + ".scene");
    sc.expected = c.contains("expected") ? folder / in.text(c["expected"], field + ".expected") : expected_dir / (sc.name + ".png");
    if (sc.expected.extension() != ".png") in.fail(field + ".expected", "expected images are 8-bit .png files");
    FrameRequest& r = sc.request;
    if (c.contains("shader")) r.shader_override = in.text(c["shader"], field + ".shader");
    if (c.contains("vert") && !c.contains("glsl")) in.fail(field + ".vert", "a vertex shader needs its fragment shader: add glsl");
    if (c.contains("glsl")) {
        if (c.contains("shader")) in.fail(field + ".glsl", "give one of shader and glsl");
        // A user's GLSL files beside the suite, compiled once per pair of files for the whole run.
        const fs::path fragment = folder / in.text(c["glsl"], field + ".glsl");
        std::optional<fs::path> vertex;
        if (c.contains("vert")) vertex = folder / in.text(c["vert"], field + ".vert");
        try {
            r.shader_override = std::string(load_glsl_shader(fragment, vertex).program->info().name);
        } catch (const std::runtime_error& e) {
            in.fail(field + ".glsl", e.what());
        }
    }
    if (c.contains("size")) {
        const std::string s = in.text(c["size"], field + ".size");
        int w = 0, h = 0;
        char x = 0, rest = 0;
        if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &rest) != 3 || x != 'x' || w < 1 || h < 1 || w > 32768 || h > 32768) {
            in.fail(field + ".size", "expected WxH within 1..32768, got '" + s + "'");
        }
        r.width = w, r.height = h;
    }
    if (c.contains("time")) r.time = in.number(c["time"], field + ".time", -1e9, 1e9);
    if (c.contains("derivatives")) {
        r.shading.derivatives = in.choice<Derivatives>(c["derivatives"], field + ".derivatives",
                                                      {{"fine", Derivatives::Fine}, {"coarse-lower", Derivatives::CoarseLower},
                                                       {"coarse-upper", Derivatives::CoarseUpper}, {"analytic", Derivatives::Analytic}});
    }
    if (c.contains("backend")) {
        r.backend = in.choice<Backend>(c["backend"], field + ".backend", {{"raster", Backend::Rasterizer}, {"raycast", Backend::RayCaster}});
    }
    if (c.contains("precision")) {
        r.shading.precision = in.choice<Precision>(c["precision"], field + ".precision", {{"float", Precision::Float}, {"double", Precision::Double}});
    }
    if (c.contains("uniforms")) {
        const json& u = c["uniforms"];
        if (!u.is_object()) in.fail(field + ".uniforms", "expected an object of NAME: number or [numbers]");
        for (const auto& [name, value] : u.items()) {
            const std::string f = field + ".uniforms." + name;
            UniformSetting s{name, {}, in.file + ": " + f};
            if (value.is_array()) {
                for (const json& v : value) s.values.push_back(in.number(v, f, -3.4e38, 3.4e38));
            } else {
                s.values.push_back(in.number(value, f, -3.4e38, 3.4e38));
            }
            r.uniforms.push_back(std::move(s));
        }
    }
    if (c.contains("tolerance")) {
        const json& t = c["tolerance"];
        const std::string f = field + ".tolerance";
        in.only(t, f, {"fail", "fail_percent", "warn", "warn_percent", "hard_fail"});
        Tolerance& tol = sc.tolerance;
        if (t.contains("fail")) tol.fail = in.number(t["fail"], f + ".fail", 0, 255);
        if (t.contains("fail_percent")) tol.fail_percent = in.number(t["fail_percent"], f + ".fail_percent", 0, 100);
        if (t.contains("warn")) tol.warn = in.number(t["warn"], f + ".warn", 0, 255);
        if (t.contains("warn_percent")) tol.warn_percent = in.number(t["warn_percent"], f + ".warn_percent", 0, 100);
        if (t.contains("hard_fail")) tol.hard_fail = in.number(t["hard_fail"], f + ".hard_fail", 0, 255);
    }
    return sc;
}

// ---- a case ----------------------------------------------------------------------------------

fs::path beside(const fs::path& expected, const char* what) {
    return expected.parent_path() / (expected.stem().string() + "." + what + ".png");
}

void remove_stale(const CaseResult& r) {
    std::error_code ec;
    fs::remove(beside(r.expected, "actual"), ec);
    fs::remove(beside(r.expected, "diff"), ec);
}

CaseResult run_case(const SuiteCase& c, bool update, int threads) {
    const auto t0 = std::chrono::steady_clock::now();
    CaseResult r;
    r.name = c.name;
    r.expected = c.expected;
    try {
        Scene scene = load_scene(c.scene);
        FrameRequest request = c.request;
        request.shading.threads = threads;
        const Framebuffer fb = render_frame(scene, request);
        const Image actual = colour_image(fb);
        r.pixels = (long long)fb.width * fb.height;
        if (update) {
            fs::create_directories(c.expected.parent_path());
            write_image(c.expected, actual, {{"quadshade:case", c.name}});
            remove_stale(r);
            r.status = CaseStatus::Updated;
        } else if (!fs::exists(c.expected)) {
            r.message = "no expected image " + c.expected.string() + " (quadshade test --update blesses one)";
        } else {
            const Image expected = read_image(c.expected);
            if (expected.width != actual.width || expected.height != actual.height) {
                r.message = "the image is " + std::to_string(actual.width) + "x" + std::to_string(actual.height) + ", the expected " +
                            std::to_string(expected.width) + "x" + std::to_string(expected.height);
            } else {
                const Tolerance& tol = c.tolerance;
                for (std::size_t p = 0; p < std::size_t(r.pixels); ++p) {
                    int worst = 0;
                    for (std::size_t ch = 0; ch < 3; ++ch) {
                        worst = std::max(worst, std::abs(int(unorm8(actual.rgba[p * 4 + ch])) - int(unorm8(expected.rgba[p * 4 + ch]))));
                    }
                    r.failing += worst > tol.fail;
                    r.warning += worst > tol.warn;
                    r.max_steps = std::max(r.max_steps, worst);
                }
                char text[256];
                const bool hard = tol.hard_fail && r.max_steps > *tol.hard_fail;
                if (hard || double(r.failing) > tol.fail_percent / 100.0 * double(r.pixels)) {
                    std::snprintf(text, sizeof text, "%lld of %lld pixels over %g/255 (allowed %g%%), max %d/255%s", r.failing,
                                  r.pixels, tol.fail, tol.fail_percent, r.max_steps, hard ? " (over hard_fail)" : "");
                    r.message = text;
                } else if (double(r.warning) > tol.warn_percent / 100.0 * double(r.pixels)) {
                    std::snprintf(text, sizeof text, "%lld of %lld pixels over %g/255 (warn above %g%%), max %d/255", r.warning,
                                  r.pixels, tol.warn, tol.warn_percent, r.max_steps);
                    r.message = text;
                    r.status = CaseStatus::Warn;
                } else {
                    r.status = CaseStatus::Pass;
                }
                if (r.status == CaseStatus::Fail) {
                    r.diff = beside(c.expected, "diff");
                    write_image(r.diff, difference_heat_map(expected, actual, 8.0f / 255.0f));
                }
            }
        }
        if (r.status == CaseStatus::Fail) {
            r.actual = beside(c.expected, "actual");
            write_image(r.actual, actual, {{"quadshade:case", c.name}});
        } else if (r.status != CaseStatus::Updated) {
            remove_stale(r);
        }
    } catch (const std::exception& e) {
        r.status = CaseStatus::Fail;
        r.message = e.what();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

}  // namespace

Suite load_suite(const fs::path& file) {
    const Reader in{file.string()};
    std::ifstream stream(file);
    if (!stream) throw std::runtime_error(file.string() + ": cannot be read");
    json doc;
    try {
        doc = json::parse(stream);
    } catch (const json::exception& e) {
        throw std::runtime_error(file.string() + ": not JSON: " + e.what());
    }
    in.only(doc, "(top level)", {"name", "expected_dir", "defaults", "cases"});
    Suite suite;
    suite.file = file;
    suite.name = doc.contains("name") ? in.text(doc["name"], "name") : file.stem().string();
    const fs::path folder = file.parent_path();
    const fs::path expected_dir = folder / (doc.contains("expected_dir") ? in.text(doc["expected_dir"], "expected_dir") : "expected");
    const json defaults = doc.contains("defaults") ? doc["defaults"] : json::object();
    if (defaults.contains("name") || defaults.contains("expected")) in.fail("defaults", "a case's name and expected image are its own");
    if (!doc.contains("cases") || !doc["cases"].is_array() || doc["cases"].empty()) in.fail("cases", "expected a non-empty array of cases");
    std::set<std::string> names;
    for (std::size_t i = 0; i < doc["cases"].size(); ++i) {
        const std::string field = "cases[" + std::to_string(i) + "]";
        if (!doc["cases"][i].is_object()) in.fail(field, "expected an object");
        SuiteCase c = read_case(in, overlay(defaults, doc["cases"][i]), field, folder, expected_dir);
        if (!names.insert(c.name).second) in.fail(field + ".name", "'" + c.name + "' is the name of an earlier case");
        suite.cases.push_back(std::move(c));
    }
    return suite;
}

SuiteRun run_suite(const SuiteRequest& request) {
    const Suite suite = load_suite(request.suite);
    SuiteRun run;
    run.suite = suite.name;
    run.shard = request.shard, run.shards = request.shards;
    run.suite_cases = suite.cases.size();
    std::vector<const SuiteCase*> mine;
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < suite.cases.size(); ++i) {
        if (int(i % std::size_t(request.shards)) == request.shard - 1) mine.push_back(&suite.cases[i]), index.push_back(i);
    }
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    const int jobs = std::clamp(request.jobs > 0 ? request.jobs : cores, 1, std::max(1, int(mine.size())));
    const int threads = std::max(1, cores / jobs);  // each case's render shares the cores with the others
    run.results.resize(mine.size());
    std::atomic<std::size_t> next{0};
    std::mutex print;
    std::size_t done = 0;
    auto worker = [&] {
        for (std::size_t k = next++; k < mine.size(); k = next++) {
            CaseResult r = run_case(*mine[k], request.update, threads);
            r.index = index[k];
            const std::lock_guard<std::mutex> lock(print);
            ++done;
            std::printf("[%*zu/%zu] %-7s %s (%.0f ms)%s%s\n", int(std::to_string(mine.size()).size()), done, mine.size(),
                        status_name(r.status), r.name.c_str(), r.seconds * 1e3, r.message.empty() ? "" : ": ", r.message.c_str());
            std::fflush(stdout);
            run.results[k] = std::move(r);
        }
    };
    std::vector<std::thread> pool;
    for (int j = 1; j < jobs; ++j) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    return run;
}

}  // namespace qs
