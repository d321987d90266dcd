#include "regression/golden_suite.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "core/framebuffer.h"
#include "images/image_io.h"
#include "regression/case_workers.h"
#include "render/glsl_shaders.h"
#include "render/memory_plan.h"
#include "scenes/gltf.h"
#include "scenes/gltf_checks.h"
#include "scenes/scene_files.h"
#include "scenes/uniforms.h"

namespace qs {

namespace fs = std::filesystem;
using nlohmann::json;

// ---- reading suite and fragment files ----------------------------------------------------------

std::string read_suite_json(const fs::path& file, std::uint64_t memory_limit) {
    std::vector<unsigned char> bytes;
    try {
        bytes = read_scene_file(file, kSuiteFileBytes, /*follow_symlink=*/true);
    } catch (const SceneError& e) {
        throw std::runtime_error(e.what());
    }
    const std::uint64_t limit = memory_limit ? memory_limit : available_memory();
    if (std::uint64_t(bytes.size()) * kJsonBytesPerByte > limit) {
        throw MemoryError(file.string() + ": " + byte_size_text(bytes.size()) + " of JSON takes about " +
                          byte_size_text(std::uint64_t(bytes.size()) * kJsonBytesPerByte) + " to read, more than the " +
                          byte_size_text(limit) + " available (--memory-limit sets it)");
    }
    return {bytes.begin(), bytes.end()};
}

void check_json_depth(std::string_view text, const std::string& file) {
    if (gltf_checks::json_nesting_depth(text, kSuiteJsonDepth) > kSuiteJsonDepth) {
        throw std::runtime_error(file + ": JSON nested more than " + std::to_string(kSuiteJsonDepth) + " levels deep");
    }
}

bool is_case_name(std::string_view n) {
    return !n.empty() && n.size() <= 200 && n[0] != '.' && std::all_of(n.begin(), n.end(), [](char ch) {
        return std::isalnum((unsigned char)ch) || ch == '-' || ch == '_' || ch == '.';
    });
}

namespace {

// `s` as a message shows it: control characters (a NUL would end the message there) as '?'.
std::string printable(std::string_view s) {
    std::string out(s.substr(0, 200));
    for (char& c : out) c = (unsigned char)c < 0x20 || c == 0x7f ? '?' : c;
    return out;
}

// ---- the suite file --------------------------------------------------------------------------

struct Reader {
    std::string file;

    [[noreturn]] void fail(const std::string& field, const std::string& what) const {
        throw std::runtime_error(file + ": " + printable(field) + ": " + what);
    }
    void only(const json& object, const std::string& field, std::initializer_list<const char*> known) const {
        if (!object.is_object()) fail(field, "expected an object");
        for (const auto& item : object.items()) {
            const std::string& key = item.key();  // not a structured binding: clang 14 captures none
            if (std::none_of(known.begin(), known.end(), [&](const char* k) { return key == k; })) {
                std::string names;
                for (const char* k : known) names += (names.empty() ? "" : ", ") + std::string(k);
                fail(field + "." + key, "unknown field (known: " + names + ")");
            }
        }
    }
    // A string without control characters: they would cut or garble the names and messages made of it.
    std::string text(const json& v, const std::string& field) const {
        if (!v.is_string()) fail(field, "expected a string");
        std::string s = v.get<std::string>();
        if (std::any_of(s.begin(), s.end(), [](char c) { return (unsigned char)c < 0x20 || c == 0x7f; })) {
            fail(field, "'" + printable(s) + "' holds a control character (such as NUL)");
        }
        return s;
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
    // A file the suite names: inside its folder unless allowed (links followed to see where they
    // lead); returned as its entry, the folder resolved and its own name kept.
    fs::path entry(const std::string& reference, const std::string& field, const SuiteLoadOptions& options) const {
        try {
            resolve_scene_uri(file, reference, {options.allow_outside}, "suite");
        } catch (const SceneError& e) {
            fail(field, e.what());
        }
        const fs::path given(reference);
        return entry_path(given.is_absolute() ? given : fs::path(file).parent_path() / given);
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

// "WxH" with both within 1..32768, nothing else.
bool parse_size(const std::string& s, int& w, int& h) {
    const std::size_t x = s.find('x');
    if (x == std::string::npos) return false;
    auto number = [](std::string_view t, int& v) {
        const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
        return !t.empty() && ec == std::errc() && end == t.data() + t.size() && v >= 1 && v <= 32768;
    };
    return number(std::string_view(s).substr(0, x), w) && number(std::string_view(s).substr(x + 1), h);
}

fs::path beside(const fs::path& expected, const char* what) {
    return expected.parent_path() / (expected.stem().string() + "." + what + ".png");
}

// A case's GLSL files, loaded once the suite is read (load_glsl).
struct CaseGlsl {
    fs::path fragment;
    std::optional<fs::path> vertex;
};

// A case's uniforms: NAME: a number or [numbers], each a shader's own uniform.
void read_uniforms(const Reader& in, const json& u, const std::string& field, std::vector<UniformSetting>& out) {
    if (!u.is_object()) in.fail(field + ".uniforms", "expected an object of NAME: number or [numbers]");
    for (const auto& [name, value] : u.items()) {
        const std::string f = field + ".uniforms." + name;
        if (!is_uniform_name(name) || name == kResolutionUniform)
            in.fail(f, "not the name of a shader's own uniform");
        UniformSetting s{name, {}, in.file + ": " + f};
        if (value.is_array()) {
            if (value.empty() || value.size() > 16) in.fail(f, "expected 1 to 16 numbers (a mat4 has 16)");
            for (const json& v : value) s.values.push_back(in.number(v, f, -3.4e38, 3.4e38));
        } else {
            s.values.push_back(in.number(value, f, -3.4e38, 3.4e38));
        }
        out.push_back(std::move(s));
    }
}

// A case's tolerance: the pixel error that fails or warns, and the share of pixels over it.
void read_tolerance(const Reader& in, const json& t, const std::string& field, Tolerance& tol) {
    const std::string f = field + ".tolerance";
    in.only(t, f, {"fail", "fail_percent", "warn", "warn_percent", "hard_fail"});
    if (t.contains("fail")) tol.fail = in.number(t["fail"], f + ".fail", 0, 255);
    if (t.contains("fail_percent")) tol.fail_percent = in.number(t["fail_percent"], f + ".fail_percent", 0, 100);
    if (t.contains("warn")) tol.warn = in.number(t["warn"], f + ".warn", 0, 255);
    if (t.contains("warn_percent")) tol.warn_percent = in.number(t["warn_percent"], f + ".warn_percent", 0, 100);
    if (t.contains("hard_fail")) tol.hard_fail = in.number(t["hard_fail"], f + ".hard_fail", 0, 255);
}

SuiteCase read_case(const Reader& in, const json& c, const std::string& field, const std::string& expected_dir,
                    const SuiteLoadOptions& options, std::optional<CaseGlsl>& glsl) {
    in.only(c, field, {"name", "scene", "shader", "glsl", "vert", "size", "time", "derivatives", "backend", "precision", "uniforms", "expected",
                       "tolerance"});
    SuiteCase sc;
    if (!c.contains("name")) in.fail(field + ".name", "missing");
    sc.name = in.text(c["name"], field + ".name");
    if (!is_case_name(sc.name))
        in.fail(field + ".name", "'" + sc.name + "': letters, digits, '-', '_' and '.' only (it names files)");
    if (!c.contains("scene")) in.fail(field + ".scene", "missing");
    const std::string scene = in.text(c["scene"], field + ".scene");
    sc.scene = in.entry(scene, field + ".scene", options);  // loaded as `render` loads the path it is given
    if (c.contains("expected")) {
        sc.expected = in.entry(in.text(c["expected"], field + ".expected"), field + ".expected", options);
    } else {
        sc.expected = in.entry(expected_dir + "/" + sc.name + ".png", "expected_dir", options);
    }
    if (sc.expected.extension() != ".png") in.fail(field + ".expected", "expected images are 8-bit .png files");
    sc.actual = beside(sc.expected, "actual"), sc.diff = beside(sc.expected, "diff");
    FrameRequest& r = sc.request;
    if (c.contains("shader")) r.shader_override = in.text(c["shader"], field + ".shader");
    if (c.contains("vert") && !c.contains("glsl")) in.fail(field + ".vert", "a vertex shader needs its fragment shader: add glsl");
    if (c.contains("glsl")) {
        if (c.contains("shader")) in.fail(field + ".glsl", "give one of shader and glsl");
        // A user's GLSL files beside the suite, compiled once per pair of files for the whole run.
        glsl = CaseGlsl{in.entry(in.text(c["glsl"], field + ".glsl"), field + ".glsl", options), std::nullopt};
        if (c.contains("vert")) glsl->vertex = in.entry(in.text(c["vert"], field + ".vert"), field + ".vert", options);
    }
    if (c.contains("size")) {
        const std::string s = in.text(c["size"], field + ".size");
        if (!parse_size(s, r.width, r.height))
            in.fail(field + ".size", "expected WxH within 1..32768, got '" + s + "'");
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
    if (c.contains("uniforms")) read_uniforms(in, c["uniforms"], field, r.uniforms);
    if (c.contains("tolerance")) read_tolerance(in, c["tolerance"], field, sc.tolerance);
    return sc;
}

// ---- a case ----------------------------------------------------------------------------------

// Bytes a case holds beside its render: its image at 8 bits per channel while the bands render,
// then for the comparison that, the expected image (decoded: up to twice its 8-bit size) and a
// chunk of the difference image's rows.
std::uint64_t comparison_bytes(std::uint64_t pixels) { return pixels * 4 * 3 + ImageWriter::kChunkBytes; }

// The difference image's colour for a largest channel difference of `steps` 8-bit steps: black,
// red, yellow, white as it grows to 8 steps (difference_heat_map's scale).
void heat_colour(int steps, float* rgba) {
    const float t = std::min(float(steps) / 8.0f, 1.0f);
    rgba[0] = std::min(3.0f * t, 1.0f);
    rgba[1] = std::clamp(3.0f * t - 1.0f, 0.0f, 1.0f);
    rgba[2] = std::clamp(3.0f * t - 2.0f, 0.0f, 1.0f);
    rgba[3] = 1.0f;
}

int largest_difference(const std::uint8_t* a, const std::uint8_t* b) {
    return std::max(
        {std::abs(int(a[0]) - int(b[0])), std::abs(int(a[1]) - int(b[1])), std::abs(int(a[2]) - int(b[2]))});
}

// The difference image, a few rows at a time.
void write_difference(const fs::path& file, const Image8& expected, const Image8& actual) {
    ImageWriter writer(file, actual.width, actual.height, false);
    const int chunk =
        int(std::clamp<std::uint64_t>(ImageWriter::kChunkBytes / (std::uint64_t(actual.width) * 32), 1, 4096));
    std::vector<float> rows;
    for (int y = 0; y < actual.height; y += chunk) {
        const int n = std::min(chunk, actual.height - y);
        rows.resize(std::size_t(n) * std::size_t(actual.width) * 4);
        const std::size_t first = std::size_t(y) * std::size_t(actual.width);
        for (std::size_t p = 0; p < rows.size() / 4; ++p) {
            heat_colour(largest_difference(&expected.rgba[(first + p) * 4], &actual.rgba[(first + p) * 4]),
                        &rows[p * 4]);
        }
        writer.write_rows(n, rows.data());
    }
    writer.commit();
}

void remove_stale(const SuiteCase& c) {
    std::error_code ec;
    fs::remove(c.actual, ec);  // a link there is removed, not what it points to
    fs::remove(c.diff, ec);
}

struct CaseSettings {
    bool update = false;
    int threads = 1;
    SceneLoadOptions load;
    MemoryBudget* budget = nullptr;
};

// The case's render as 8-bit RGBA (GL's unorm conversion, alpha 255), band by band within the budget.
Image8 render_case(const SuiteCase& c, const CaseSettings& settings, std::optional<MemoryBudget::Reservation>& held) {
    Scene scene = load_scene(c.scene, settings.load);
    FrameRequest request = c.request;
    request.shading.threads = settings.threads;
    SceneRenderer renderer(scene, request);
    const int w = renderer.width(), h = renderer.height();
    const std::uint64_t pixels = std::uint64_t(w) * std::uint64_t(h);
    MemoryPlanInput plan;
    plan.height = h;
    plan.pairing = request.shading.pairing;
    plan.limit = settings.budget->limit();
    plan.can_band = true;
    plan.bytes_for_rows = [&](int rows) { return renderer.frame_bytes(rows) + pixels * 4; };
    const std::vector<RowBand> bands = plan_bands(plan);
    int rows = 0;
    for (const RowBand& b : bands) rows = std::max(rows, b.end - b.begin);
    held.emplace(
        settings.budget->reserve(std::max(plan.bytes_for_rows(rows), comparison_bytes(pixels)),
                                 "case '" + c.name + "' (" + std::to_string(w) + "x" + std::to_string(h) + ")"));
    Image8 image{w, h, std::vector<std::uint8_t>(std::size_t(pixels) * 4)};
    Framebuffer fb;
    for (const RowBand& band : bands) {
        renderer.render_into(fb, std::nullopt, nullptr, band);
        std::uint8_t* out = &image.rgba[std::size_t(fb.first_row) * std::size_t(w) * 4];
        const std::size_t n = std::size_t(fb.rows) * std::size_t(w);
        for (std::size_t p = 0; p < n; ++p) {
            for (std::size_t ch = 0; ch < 3; ++ch) out[p * 4 + ch] = unorm8(fb.rgba[p * 4 + ch]);
            out[p * 4 + 3] = 255;
        }
    }
    return image;
}

CaseResult run_case(const SuiteCase& c, const CaseSettings& settings) {
    const auto t0 = std::chrono::steady_clock::now();
    CaseResult r;
    r.name = c.name;
    r.expected = c.expected;
    try {
        std::optional<MemoryBudget::Reservation> held;
        const Image8 actual = render_case(c, settings, held);
        r.pixels = (long long)actual.width * actual.height;
        if (settings.update) {
            make_output_folder(c.expected.parent_path(), FolderLink::Followed);
            write_image(c.expected, actual, {{"quadshade:case", c.name}});
            remove_stale(c);
            r.status = CaseStatus::Updated;
        } else if (std::error_code ec; !fs::exists(c.expected, ec)) {
            r.message = "no expected image " + c.expected.string() + " (quadshade test --update blesses one)";
        } else {
            ImageReadLimits limits;  // the render's size, checked on the header before anything is decoded
            limits.width = actual.width, limits.height = actual.height;
            const Image8 expected = read_image8(c.expected, limits);
            const Tolerance& tol = c.tolerance;
            for (std::size_t p = 0; p < std::size_t(r.pixels); ++p) {
                const int worst = largest_difference(&actual.rgba[p * 4], &expected.rgba[p * 4]);
                r.failing += worst > tol.fail;
                r.warning += worst > tol.warn;
                r.max_steps = std::max(r.max_steps, worst);
            }
            char text[256];
            const bool hard = tol.hard_fail && r.max_steps > *tol.hard_fail;
            if (hard || double(r.failing) > tol.fail_percent / 100.0 * double(r.pixels)) {
                std::snprintf(text, sizeof text, "%lld of %lld pixels over %g/255 (allowed %g%%), max %d/255%s",
                              r.failing, r.pixels, tol.fail, tol.fail_percent, r.max_steps,
                              hard ? " (over hard_fail)" : "");
                r.message = text;
            } else if (double(r.warning) > tol.warn_percent / 100.0 * double(r.pixels)) {
                std::snprintf(text, sizeof text, "%lld of %lld pixels over %g/255 (warn above %g%%), max %d/255",
                              r.warning, r.pixels, tol.warn, tol.warn_percent, r.max_steps);
                r.message = text;
                r.status = CaseStatus::Warn;
            } else {
                r.status = CaseStatus::Pass;
            }
            if (r.status == CaseStatus::Fail) {
                r.diff = c.diff;
                write_difference(r.diff, expected, actual);
            }
        }
        if (r.status == CaseStatus::Fail) {
            r.actual = c.actual;
            write_image(r.actual, actual, {{"quadshade:case", c.name}});
        } else if (r.status != CaseStatus::Updated) {
            remove_stale(c);
        }
    } catch (const std::exception& e) {
        r.status = CaseStatus::Fail;
        r.message = e.what();
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

}  // namespace

Suite load_suite(const fs::path& file, const SuiteLoadOptions& options) {
    return parse_suite(read_suite_json(file, options.memory_limit), file, options);
}

Suite parse_suite(std::string_view text, const fs::path& file, const SuiteLoadOptions& options) {
    const Reader in{file.string()};
    check_json_depth(text, in.file);
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception& e) {
        throw std::runtime_error(in.file + ": not JSON: " + e.what());
    }
    in.only(doc, "(top level)", {"name", "expected_dir", "defaults", "cases"});
    Suite suite;
    suite.file = file;
    suite.name = doc.contains("name") ? in.text(doc["name"], "name") : file.stem().string();
    const std::string expected_dir =
        doc.contains("expected_dir") ? in.text(doc["expected_dir"], "expected_dir") : "expected";
    const json defaults = doc.contains("defaults") ? doc["defaults"] : json::object();
    if (!defaults.is_object()) in.fail("defaults", "expected an object of case fields");
    if (defaults.contains("name") || defaults.contains("expected")) in.fail("defaults", "a case's name and expected image are its own");
    if (!doc.contains("cases") || !doc["cases"].is_array() || doc["cases"].empty()) in.fail("cases", "expected a non-empty array of cases");
    if (doc["cases"].size() > kSuiteCases) in.fail("cases", "more than " + std::to_string(kSuiteCases) + " cases");
    // Every file a case writes (its expected image on --update, a failure's actual and difference
    // images) belongs to that case alone: a pass removes its stale ones, so a file two cases
    // share would be one case's image removed or overwritten by the other.
    std::map<std::string, std::pair<std::size_t, const char*>> owner;
    std::set<std::string> names;
    // Each pair of GLSL files, with the cases that draw it (the first names it in a message).
    std::map<std::pair<std::string, std::string>, std::pair<CaseGlsl, std::vector<std::size_t>>> glsl_cases;
    for (std::size_t i = 0; i < doc["cases"].size(); ++i) {
        const std::string field = "cases[" + std::to_string(i) + "]";
        if (!doc["cases"][i].is_object()) in.fail(field, "expected an object");
        std::optional<CaseGlsl> glsl;
        SuiteCase c = read_case(in, overlay(defaults, doc["cases"][i]), field, expected_dir, options, glsl);
        if (glsl) {
            auto& [files, cases] = glsl_cases[{glsl->fragment.string(), glsl->vertex ? glsl->vertex->string() : ""}];
            files = *glsl;
            cases.push_back(i);
        }
        if (!names.insert(c.name).second) in.fail(field + ".name", "'" + c.name + "' is the name of an earlier case");
        for (const auto& [file_of, role] :
             {std::pair{&c.expected, "expected image"}, std::pair{&c.actual, "actual image"},
              std::pair{&c.diff, "difference image"}}) {
            const auto [it, added] = owner.emplace(file_of->string(), std::pair{i, role});
            if (!added) {
                in.fail(field + ".expected", "its " + std::string(role) + " " + file_of->string() + " is case '" +
                                                 suite.cases[it->second.first].name + "''s " + it->second.second +
                                                 " (the actual and difference images of a failure are kept beside the "
                                                 "expected image, as NAME.actual.png and NAME.diff.png)");
            }
        }
        suite.cases.push_back(std::move(c));
    }
    // Compiled once for what all its cases ask, where it runs compiled (render/compiled_glsl.h).
    for (const auto& [key, files_and_cases] : glsl_cases) {
        const auto& [files, cases] = files_and_cases;
        std::vector<ShadeRequest> shading;
        for (std::size_t i : cases) shading.push_back(shade_request(suite.cases[i].request));
        std::string shader;
        try {
            shader = std::string(load_glsl_shader(files.fragment, files.vertex, options.glsl_way, shading).program->info().name);
        } catch (const std::runtime_error& e) {
            in.fail("cases[" + std::to_string(cases.front()) + "].glsl", e.what());
        }
        for (std::size_t i : cases) suite.cases[i].request.shader_override = shader;
    }
    suite.inputs.add(file);
    return suite;
}

void add_scene_inputs(Suite& suite, const SuiteLoadOptions& options) {
    std::set<fs::path> scenes;
    for (const SuiteCase& c : suite.cases) scenes.insert(c.scene);
    SceneLoadOptions load;
    load.paths.allow_outside = options.allow_outside;
    for (const fs::path& file : scenes) {
        suite.inputs.add(file);
        try {
            for (const fs::path& input : load_scene(file, load).inputs) suite.inputs.add(input);
        } catch (const std::exception&) {
            // Its cases fail with the message.
        }
    }
}

SuiteRun run_suite(const Suite& suite, const SuiteRequest& request) {
    SuiteRun run;
    run.suite = suite.name;
    run.shard = request.shard, run.shards = request.shards;
    run.suite_cases = suite.cases.size();
    std::vector<const SuiteCase*> mine;
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < suite.cases.size(); ++i) {
        if (int(i % std::size_t(request.shards)) == request.shard - 1) mine.push_back(&suite.cases[i]), index.push_back(i);
    }
    // What the cases write, checked before any of them runs: never a file the suite reads.
    for (std::size_t k = 0; k < mine.size(); ++k) {
        const SuiteCase& c = *mine[k];
        const std::string field = suite.file.string() + ": cases[" + std::to_string(index[k]) + "]";
        auto refuse = [&](const fs::path& output, const char* what) {
            throw std::runtime_error(
                field + ": its " + std::string(what) + " " + output.string() +
                " is a file the suite reads (the suite, a scene or a file a scene names): it would "
                "be overwritten");
        };
        if (request.update && suite.inputs.contains(c.expected)) refuse(c.expected, "expected image");
        if (suite.inputs.contains(c.actual)) refuse(c.actual, "failure's actual image");
        if (suite.inputs.contains(c.diff)) refuse(c.diff, "failure's difference image");
    }
    const CaseWorkers workers = case_workers(request.jobs, mine.size());
    MemoryBudget budget(request.load.memory_limit ? request.load.memory_limit : available_memory());
    CaseSettings settings;
    settings.update = request.update;
    settings.threads = workers.threads;  // each case's render shares the cores with the others
    settings.load.paths.allow_outside = request.load.allow_outside;
    settings.budget = &budget;
    run.results.resize(mine.size());
    std::mutex print;
    std::size_t done = 0;
    run_cases(workers.jobs, mine.size(), [&](int, std::size_t k) {
        CaseResult r = run_case(*mine[k], settings);
        r.index = index[k];
        const std::lock_guard<std::mutex> lock(print);
        ++done;
        std::printf("[%*zu/%zu] %-7s %s (%.0f ms)%s%s\n", int(std::to_string(mine.size()).size()), done, mine.size(),
                    status_name(r.status), r.name.c_str(), r.seconds * 1e3, r.message.empty() ? "" : ": ",
                    r.message.c_str());
        std::fflush(stdout);
        run.results[k] = std::move(r);
        return true;
    });
    return run;
}

}  // namespace qs
