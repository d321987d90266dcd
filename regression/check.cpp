#include "regression/check.h"

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <mutex>
#include <cstring>

#include "core/framebuffer.h"
#include "files/output_file.h"
#include "files/temporary_file.h"
#include "raster/driver_settings.h"
#include "regression/case_workers.h"
#include "render/frame_image.h"
#include "render/memory_plan.h"
#include "render/reference_process.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"

namespace qs {

namespace fs = std::filesystem;

namespace {

// ---- the rules and their references --------------------------------------------------------

const char* rule_name(CheckRule r) { return r == CheckRule::Fine ? "fine" : "coarse-lower"; }
const char* driver_of(CheckRule r) { return r == CheckRule::Fine ? "llvmpipe" : "softpipe"; }

// The bar, as fractions of the covered pixels (coverage: of all pixels). Against llvmpipe, the
// project's. Against softpipe, room for what its own arithmetic does to shaders that translate
// their GLSL exactly (design.md, "Not reproduced exactly"; the conformance tests' softpipe bounds):
// it sets up edges in floating point without sub-pixel snapping, so a pixel whose centre lies
// within 1/256 pixel of an edge may be covered by one and not the other (2 of 12288 pixels on the
// slivers at 128x96), and it interpolates varyings with its own rounding, which moves pixels of
// discontinuous patterns and of anti-aliased edges (the most: the spots on the grazing plane, 117
// pixels over 1/255 and 87 over 2/255 at 259x143). A translation error moves far more (the test's
// mistranslated stripes: 8% to 90% of the covered pixels).
struct Fractions {
    double over_1, over_2, coverage;
};
constexpr Fractions kFineBar{0.001, 0.0, 0.0};
constexpr Fractions kCoarseLowerBar{0.006, 0.005, 0.0002};

struct Bar {
    std::size_t over_1 = 0, over_2 = 0, coverage = 0;
    std::string cause;  // empty: the default bar
};

Bar bar_for(const ShaderInfo& info, const std::string& scene, CheckRule rule, const CaseCounts& n) {
    for (const CheckBound& b : info.check_bounds) {
        if ((b.scene.empty() || b.scene == scene) && (b.rule.empty() || b.rule == rule_name(rule))) {
            return {b.over_1, b.over_2, b.coverage, std::string(b.cause)};
        }
    }
    const Fractions f = rule == CheckRule::Fine ? kFineBar : kCoarseLowerBar;
    auto of = [](double fraction, std::size_t total) { return std::size_t(std::floor(fraction * double(total))); };
    if (rule == CheckRule::CoarseLower && samples_textures(info.needs)) {
        return {n.pixels, n.pixels, of(f.coverage, n.pixels),
                "softpipe's level of detail and mipmaps are its own (design.md): colours counted, coverage held"};
    }
    return {of(f.over_1, n.covered), of(f.over_2, n.covered), of(f.coverage, n.pixels), {}};
}

bool meets(const CaseCounts& n, const Bar& bar) {
    return n.coverage <= bar.coverage && n.over_1 <= bar.over_1 && n.over_2 <= bar.over_2;
}

// ---- where things are ------------------------------------------------------------------------

bool is_scene_file(const fs::path& p) {
    std::string ext = p.extension().string();
    for (char& c : ext) c = char(std::tolower((unsigned char)c));
    return ext == ".gltf" || ext == ".glb";
}

// The scene files of `folder`, by name.
std::vector<fs::path> scenes_in(const fs::path& folder) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) throw std::runtime_error("--scenes " + folder.string() + ": not a folder");
    std::vector<fs::path> files;
    for (const fs::directory_entry& e : fs::directory_iterator(folder)) {
        if (e.is_regular_file() && is_scene_file(e.path())) files.push_back(e.path());
    }
    if (files.empty()) throw std::runtime_error("--scenes " + folder.string() + ": no .gltf or .glb scene in it");
    std::sort(files.begin(), files.end());
    return files;
}

// The scenes --scenes names: files as they are, folders as the scenes in them.
std::vector<fs::path> named_scenes(const std::vector<fs::path>& named) {
    std::vector<fs::path> files;
    for (const fs::path& p : named) {
        std::error_code ec;
        if (fs::is_directory(p, ec)) {
            for (const fs::path& f : scenes_in(p)) files.push_back(f);
        } else if (!fs::is_regular_file(p, ec)) {
            throw std::runtime_error("--scenes " + p.string() + ": no such file or folder");
        } else if (!is_scene_file(p)) {
            throw std::runtime_error("--scenes " + p.string() + ": not a .gltf or .glb scene");
        } else {
            files.push_back(p);
        }
    }
    return files;
}

}  // namespace

fs::path installed_scenes_folder() { return executable_folder().parent_path() / "share" / "quadshade" / "scenes"; }

namespace {

std::vector<fs::path> default_scenes() {
    const fs::path folder = installed_scenes_folder();
    std::vector<fs::path> files = scenes_in(folder / "conformance");
    const fs::path plane = folder / "table-1.1-plane.gltf";
    if (!fs::exists(plane)) throw std::runtime_error(plane.string() + ": the Table 1.1 plane is missing (an incomplete installation?)");
    files.push_back(plane);
    return files;
}

// ---- cases -----------------------------------------------------------------------------------

// The named shaders; by default the catalogue's but its probes (built-ins' tests of their own,
// drawn for one window and reading undefined GLSL cases elsewhere, as the conformance tests
// leave them out), plugins' included.
std::vector<const Program*> shaders_of(const CheckRequest& request) {
    if (request.shaders.empty()) {
        std::vector<const Program*> all;
        for (const Program* p : catalogue()) {
            const bool probe = plugin_of(*p).empty() && p->info().name.ends_with("_probe");
            if (!probe) all.push_back(p);
        }
        return all;
    }
    std::vector<const Program*> programs;
    for (const std::string& name : request.shaders) {
        const Program* p = find_program(name);
        if (!p) throw std::runtime_error("unknown shader '" + name + "' (quadshade shaders lists the catalogue; --plugin LIB adds a plugin's)");
        programs.push_back(p);
    }
    return programs;
}

std::string percent(std::size_t n, std::size_t of) {
    char s[32];
    std::snprintf(s, sizeof s, "%.3f%%", of ? 100.0 * double(n) / double(of) : 0.0);
    return s;
}

}  // namespace

CaseCounts count_differences(const Image& ours, const Image& reference) {
    if (ours.width != reference.width || ours.height != reference.height) {
        throw std::runtime_error("the images differ in size: " + std::to_string(ours.width) + "x" + std::to_string(ours.height) +
                                 " and " + std::to_string(reference.width) + "x" + std::to_string(reference.height));
    }
    CaseCounts c;
    c.pixels = std::size_t(ours.width) * std::size_t(ours.height);
    for (std::size_t p = 0; p < c.pixels; ++p) {
        const float* a = &ours.rgba[p * 4];
        const float* b = &reference.rgba[p * 4];
        c.covered += b[3] > 0.5f;
        // A shader that writes its own alpha may put it at 1/2, where one 8-bit step is no coverage.
        c.coverage += (a[3] > 0.5f) != (b[3] > 0.5f) && std::abs(int(unorm8(a[3])) - int(unorm8(b[3]))) > 1;
        int worst = 0;
        for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, std::abs(int(unorm8(a[ch])) - int(unorm8(b[ch]))));
        c.over_1 += worst > 1;
        c.over_2 += worst > 2;
        if (worst > c.max_steps) {
            c.max_steps = worst;
            c.max_x = int(p % std::size_t(ours.width)), c.max_y = int(p / std::size_t(ours.width));
        }
    }
    return c;
}

namespace {

struct Case {
    std::size_t scene;  // index into the scene files
    const Program* program;
    CheckRule rule;
};

struct CaseReport {
    bool done = false, ok = false;
    CaseCounts counts;
    Bar bar;
    int width = 0, height = 0;
    std::string heat_map, error;
};

// Bytes a case holds per pixel beside its render, at most: our image and the reference's (16
// each), the reference's decoding (16 more), the heat map and its intermediates (80), the
// side-by-side strip (48), and the reference process (56: 55 measured at 2048x2048).
constexpr std::uint64_t kCheckBytesPerPixel = 232;

struct Checker {
    const CheckRequest& request;
    fs::path reference, glsl;
    std::vector<fs::path> files;
    std::vector<Scene> scenes;
    InputFiles inputs;  // the scenes and the files they read: never written over
    MemoryBudget* budget = nullptr;
    int threads = 1;  // per render

    // One case, its reference rendered by a quadshade-reference process writing `image`.
    CaseReport run(const Case& c, const fs::path& image, const fs::path& log) const {
        CaseReport report;
        const ShaderInfo& info = c.program->info();
        const std::string shader(info.name), scene_name = files[c.scene].stem().string();
        Scene scene = scenes[c.scene];
        FrameRequest r;
        r.shader_override = shader;
        r.set(raster_options_as(c.rule == CheckRule::Fine ? MesaDriver::Llvmpipe : MesaDriver::Softpipe));
        r.shading.threads = threads;
        r.width = request.width, r.height = request.height;
        SceneRenderer renderer(scene, r);
        const int w = renderer.width(), h = renderer.height();
        const MemoryBudget::Reservation held =
            budget->reserve(renderer.frame_bytes(h) + std::uint64_t(w) * std::uint64_t(h) * kCheckBytesPerPixel,
                            "checking " + shader + " on " + files[c.scene].string() + " (" + std::to_string(w) + "x" +
                                std::to_string(h) + ")");
        std::vector<std::string> argv = {reference.string(), files[c.scene].string(), "-o", image.string(), "--glsl",
                                         glsl.string(), "--driver", driver_of(c.rule), "--shader", shader};
        if (request.width > 0) {
            argv.insert(argv.end(), {"--size", std::to_string(request.width) + "x" + std::to_string(request.height)});
        }
        if (const int status = run_process(argv, log); status != 0) {
            throw std::runtime_error("quadshade-reference failed on " + files[c.scene].string() + " with " + shader + " (" +
                                     driver_of(c.rule) + ", exit " + std::to_string(status) + "): " + read_text(log));
        }
        ImageReadLimits limits;  // the scene's size, checked on the header
        limits.width = w, limits.height = h;
        const Image theirs = read_image(image, limits);
        Framebuffer fb;
        renderer.render_into(fb, std::nullopt);
        const Image ours = colour_image(fb);
        fb = {};
        report.width = w, report.height = h;
        report.counts = count_differences(ours, theirs);
        report.bar = bar_for(info, scene_name, c.rule, report.counts);
        report.ok = meets(report.counts, report.bar);
        if (report.counts.coverage || report.counts.max_steps) {
            const fs::path f = request.output / (scene_name + "-" + shader + "-" + rule_name(c.rule) + ".png");
            if (inputs.contains(f))
                throw std::runtime_error(f.string() + ": a file a scene reads; check's heat map would overwrite it");
            const Image diff = difference_heat_map(ours, theirs, 8.0f / 255.0f);
            write_image(f, side_by_side({&ours, &theirs, &diff}));
            report.heat_map = f.string();
        }
        return report;
    }

    // The shader of case `c` shaded once in its checked instantiation, which throws where a
    // Loop's body writes a variable the loop does not hold; empty when none does. A body's writes
    // happen whichever of its lanes are live (an `if` is a select), so a frame of at most 128
    // pixels a side finds them unless only pixels it skips run that iteration, at a fraction of
    // the checked instantiation's cost at the case's size.
    std::string loop_writes(const Case& c) const {
        Scene scene = scenes[c.scene];
        FrameRequest r;
        r.shader_override = std::string(c.program->info().name);
        r.set(raster_options_as(MesaDriver::Llvmpipe));
        r.shading.threads = threads;
        r.shading.check_undefined = true;
        const bool sized = request.width > 0;
        const int w = sized ? request.width : scene.width, h = sized ? request.height : scene.height;
        const double scale = std::min(1.0, 128.0 / double(std::max(w, h)));
        r.width = std::max(1, int(w * scale)), r.height = std::max(1, int(h * scale));
        try {
            render_frame(scene, r);
        } catch (const std::logic_error& e) {
            return e.what();
        }
        return {};
    }

    void print(const Case& c, const CaseReport& r) const {
        const std::string shader(c.program->info().name), scene_name = files[c.scene].stem().string();
        const CaseCounts& n = r.counts;
        std::printf("%s %-34s %-22s %-12s %7zu covered  coverage %zu  over 1/255 %zu (%s)  over 2/255 %zu  max %d/255",
                    r.ok ? "ok  " : "FAIL", scene_name.c_str(), shader.c_str(), rule_name(c.rule), n.covered, n.coverage, n.over_1,
                    percent(n.over_1, n.covered).c_str(), n.over_2, n.max_steps);
        if (n.max_steps) std::printf(" at (%d, %d)", n.max_x, n.max_y);
        if (!r.ok) std::printf("\n     bar: coverage %zu, over 1/255 %zu, over 2/255 %zu", r.bar.coverage, r.bar.over_1, r.bar.over_2);
        if (!r.bar.cause.empty()) std::printf("\n     the shader's bound: %s", r.bar.cause.c_str());
        if (!r.heat_map.empty()) std::printf("\n     quadshade | OSMesa | heat map (full scale 8/255): %s", r.heat_map.c_str());
        std::printf("\n");
        std::fflush(stdout);
    }

    // The case's row of report.csv (kReportColumns).
    void write_row(const Case& c, const CaseReport& r, std::ostream& csv) const {
        const std::string shader(c.program->info().name), scene_name = files[c.scene].stem().string();
        const CaseCounts& n = r.counts;
        csv << scene_name << "," << shader << "," << rule_name(c.rule) << "," << driver_of(c.rule) << "," << r.width << "," << r.height
            << "," << n.covered << "," << n.coverage << "," << n.over_1 << "," << n.over_2 << "," << n.max_steps << "," << n.max_x
            << "," << n.max_y << "," << r.bar.over_1 << "," << r.bar.over_2 << "," << r.bar.coverage << "," << (r.ok ? "ok" : "fail")
            << "\n";
    }
};

constexpr const char* kReportColumns =
    "scene,shader,rule,driver,width,height,covered,coverage_mismatch,over_1,over_2,max_steps,max_x,max_y,"
    "bar_over_1,bar_over_2,bar_coverage,result\n";

struct CaseList {
    std::vector<Case> cases;
    std::size_t skipped_pairs = 0;  // shader-scene pairs left out
};

// Loads the checker's scene files and lists the cases: each scene with every shader that it can
// feed, under every rule asked for.
CaseList list_cases(Checker& checker, const std::vector<const Program*>& programs) {
    const CheckRequest& request = checker.request;
    CaseList list;
    for (std::size_t s = 0; s < checker.files.size(); ++s) {
        checker.scenes.push_back(load_scene(checker.files[s]));
        for (const fs::path& input : checker.scenes.back().inputs) checker.inputs.add(input);
        for (const Program* program : programs) {
            // The default set's texture scenes (generators/texture_scenes.h) test sampling: they are for
            // the shaders that sample a texture; the others are checked on the geometry scenes.
            const bool texture_scene = request.scenes.empty() && checker.files[s].stem().string().starts_with("texture-");
            if (!binds_samplers(checker.scenes.back(), program->info()) ||
                (texture_scene && !samples_textures(program->info().needs))) {
                ++list.skipped_pairs;
                continue;
            }
            for (const CheckRule rule : request.rules) list.cases.push_back({s, program, rule});
        }
    }
    if (list.cases.empty()) {
        throw std::runtime_error("no case to check: no scene binds the textures the shaders sample");
    }
    return list;
}

// The report, the exported GLSL's folder and the output folder itself, made before any case runs;
// none may be a file a scene reads.
void make_outputs(const Checker& checker, const fs::path& report_file) {
    for (const fs::path& output : {report_file, checker.glsl}) {
        if (checker.inputs.contains(output))
            throw std::runtime_error(output.string() + ": a file a scene reads; check would overwrite it");
    }
    make_output_folder(checker.request.output, FolderLink::Followed);
    output_place(report_file, Streams::Refused);
    make_output_folder(checker.glsl, FolderLink::Refused);
}

// Each shader's loops, on its first case: a line for each shader that fails; returns their number.
std::size_t check_loops(const Checker& checker, const std::vector<const Program*>& programs,
                        const std::vector<Case>& cases) {
    std::size_t failures = 0;
    for (const Program* program : programs) {
        for (const Case& c : cases) {
            if (c.program != program) continue;
            if (const std::string problem = checker.loop_writes(c); !problem.empty()) {
                std::printf("FAIL %s: %s\n", std::string(program->info().name).c_str(), problem.c_str());
                std::fflush(stdout);
                ++failures;
            }
            break;
        }
    }
    return failures;
}

// Runs the cases, request.jobs at once, and prints each report and writes its row in case order as
// they complete; returns the number that failed. The first error stops the workers, and the
// error of the earliest case that had one is thrown once they have stopped.
std::size_t run_in_order(Checker& checker, const std::vector<Case>& cases, const fs::path& scratch, std::ostream& csv) {
    const CaseWorkers workers = case_workers(checker.request.jobs, cases.size());
    checker.threads = workers.threads;
    std::vector<CaseReport> reports(cases.size());
    std::mutex lock;
    std::size_t printed = 0, failed = 0;
    run_cases(workers.jobs, cases.size(), [&](int worker, std::size_t k) {
        const fs::path image = scratch / ("reference-" + std::to_string(worker) + ".exr");
        const fs::path log = scratch / ("reference-" + std::to_string(worker) + ".log");
        CaseReport r;
        try {
            r = checker.run(cases[k], image, log);
        } catch (const std::exception& e) {
            r.error = e.what();
        }
        r.done = true;
        const bool go_on = r.error.empty();
        const std::lock_guard<std::mutex> guard(lock);
        reports[k] = std::move(r);
        for (; printed < cases.size() && reports[printed].done && reports[printed].error.empty(); ++printed) {
            checker.print(cases[printed], reports[printed]);
            checker.write_row(cases[printed], reports[printed], csv);
            failed += !reports[printed].ok;
        }
        return go_on;
    });
    for (const CaseReport& r : reports) {
        if (!r.error.empty()) throw std::runtime_error(r.error);
    }
    return failed;
}

struct Tally {
    std::size_t cases = 0, shaders = 0, scenes = 0, rules = 0;
    std::size_t failed = 0, loop_failures = 0, skipped_pairs = 0;
    double seconds = 0.0;
};

void print_summary(const Tally& t, bool default_scenes) {
    std::printf("quadshade check: %zu cases (%zu shaders, %zu scenes, %zu rule%s) in %.1f s: %zu passed, %zu failed",
                t.cases, t.shaders, t.scenes, t.rules, t.rules == 1 ? "" : "s", t.seconds, t.cases - t.failed,
                t.failed);
    if (t.loop_failures) {
        std::printf("; %zu shader%s with a loop that does not hold what it writes", t.loop_failures,
                    t.loop_failures == 1 ? "" : "s");
    }
    if (t.skipped_pairs) {
        std::printf("; %zu shader-scene pairs left out (the scene binds no texture the shader samples%s)",
                    t.skipped_pairs, default_scenes ? ", or the shader samples none on a texture scene" : "");
    }
}

}  // namespace

int run_check(const CheckRequest& request) {
    Checker checker{request, reference_executable("check"), request.output / "glsl", {}, {}, {}, nullptr, 1};
    const std::vector<const Program*> programs = shaders_of(request);
    checker.files = request.scenes.empty() ? default_scenes() : named_scenes(request.scenes);
    const CaseList list = list_cases(checker, programs);
    const fs::path report_file = request.output / "report.csv";
    make_outputs(checker, report_file);
    Tally tally{list.cases.size(), programs.size(), checker.files.size(), request.rules.size()};
    tally.skipped_pairs = list.skipped_pairs;
    tally.loop_failures = check_loops(checker, programs, list.cases);
    export_glsl(checker.glsl);  // the reference sees the GLSL as any GL application would: the text only
    // The reference images and logs are this run's own (two runs may share -o); the report is
    // written whole once every case is done.
    const ScratchFolder scratch(request.output / "reference");
    MemoryBudget budget(request.memory_limit ? request.memory_limit : available_memory());
    checker.budget = &budget;
    std::ostringstream csv;
    csv << kReportColumns;
    const auto start = std::chrono::steady_clock::now();
    tally.failed = run_in_order(checker, list.cases, scratch.path(), csv);
    tally.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    print_summary(tally, request.scenes.empty());
    write_output(report_file, csv.str());
    std::printf("\nquadshade check: report %s\n", report_file.string().c_str());
    return tally.failed || tally.loop_failures ? 3 : 0;
}

}  // namespace qs
