// quadshade-bench-throughput: Table 1.1's shaders on the Table 1.1 plane, quadshade next to OSMesa
// llvmpipe at its best in one run on the same cores (LP_NUM_THREADS = quadshade's thread count),
// next to the book's 2011 GPU figures. Frames are timed after set-up (context creation and GLSL
// compilation are reported separately); llvmpipe frames end with glFinish. Both render into a
// float RGBA target, as the reference comparisons do.
//
// llvmpipe reads LP_NATIVE_VECTOR_WIDTH once per process, so each of its rows runs in a child
// process per width (this program re-executed with --peer-only and an explicit environment),
// right after quadshade's frames of the same row; quadshade is compared with the faster width.
// This host's speed drifts between minutes, so the whole table is measured in rounds: each round
// times every row (and the Figure 1.1 frame) in turn, each ratio is taken within a round, and a
// cell is the median over the rounds with their range. Within a round it drifts over seconds too,
// so quadshade's frames are timed both before and after llvmpipe's and pooled: a host that slows
// or speeds up during the round moves both sides of the ratio alike.
//
//   quadshade-bench-throughput [--threads N] [--repeat N] [--rounds N] [--sizes 1024,500] [--shaders a,b]
//                              [--widths 256,512] [--out DIR]
//   quadshade-bench-throughput --scaling [--scaling-threads 1,2,8] [--rounds N] [--sizes 1024] [--out DIR]
//   quadshade-bench-throughput --interpreted|--generated [--threads N] [--rounds N] [--sizes 1024] [--out DIR]
// Writes DIR/throughput.csv, throughput.md, specialisation.md and figure-1.1-frame.md (or, with
// --scaling, DIR/scaling.md; with --interpreted or --generated, each row's GLSL run that way
// beside its hand translation, DIR/interpreter.md or DIR/generated.md) and prints the Markdown
// tables.

#include <algorithm>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <sys/resource.h>

#include <CLI/CLI.hpp>

#include "bench/child_process.h"
#include "bench/peer_report.h"
#include "reference/gl_renderer.h"
#include "render/compiled_glsl.h"
#include "render/glsl_shaders.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"
#include "shading/catalogue.h"
#include "shading/glsl_export.h"
#include "shading/shade_choice.h"

namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

struct Row {
    const char* shader;
    const char* book_name;
    int book[4];  // Mfrag/s on NVIDIA 9600M, AMD HD6310, AMD HD4850, NVIDIA GTX260 (Gustavson's Table 1.1)
    bool noise;   // a noise row of the scaling table
};
const Row kRows[] = {
    {"constant_color", "Constant color", {422, 430, 2721, 3610}, false},
    {"single_texture", "Single texture", {412, 414, 2718, 3610}, false},
    {"dots", "Dots (Fig 1.2)", {360, 355, 2720, 3420}, false},
    {"perlin", "Perlin noise (Fig 1.4)", {63, 97, 1042, 697}, true},
    {"perlin5", "5x Perlin (Fig 1.4)", {11, 23, 271, 146}, true},
    {"worley", "Worley noise (Fig 1.5)", {82, 116, 1192, 787}, true},
    {"worley_tiles", "Worley tiles (Fig 1.5)", {26, 51, 580, 345}, true},
    {"halftone", "Halftone (Fig 1.6)", {34, 52, 597, 373}, false},
};

const fs::path kSource = QUADSHADE_SOURCE_DIR;
const fs::path kPlane = kSource / "scenes/assets/table-1.1-plane.gltf";
const fs::path kFigure = kSource / "scenes/assets/figure-1.1.gltf";

struct Options {
    int threads = 2, repeat = 15;
    std::vector<int> sizes = {1024, 500};
    std::string out = "bench-results";
    std::vector<std::string> shaders;  // these rows only, and no Figure 1.1 frame
    std::vector<int> widths = {256, 512};
    bool scaling = false;
    bool interpreted = false, generated = false;
    std::vector<int> scaling_threads = {1, 2, 8};
    int rounds = 3;
    // A peer child's job (--peer-only): one llvmpipe row, or the Figure 1.1 frame.
    bool peer_only = false;
    int vector_width = 0;
    int size = 0;
    std::string shader;
    bool figure = false;
    std::string glsl;
};

struct Stats {
    double median = 0, min = 0, max = 0;  // ms per frame
};
Stats stats_of(std::vector<double> ms) {
    std::sort(ms.begin(), ms.end());
    return {ms[ms.size() / 2], ms.front(), ms.back()};
}

// Each frame's time, after a warm-up frame, appended to `ms`.
template <class F>
void time_frames_into(std::vector<double>& ms, int repeat, F&& frame) {
    frame();  // warm-up
    for (int i = 0; i < repeat; ++i) {
        const auto t0 = Clock::now();
        frame();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
}

template <class F>
Stats time_frames(int repeat, F&& frame) {
    std::vector<double> ms;
    time_frames_into(ms, repeat, frame);
    return stats_of(ms);
}

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

std::string format(const char* fmt, auto... args) {
    char line[1024];
    std::snprintf(line, sizeof line, fmt, args...);
    return line;
}

// ---- the peer child: llvmpipe at the width its environment sets ---------------------------

int run_peer_child(const Options& o) {
    const char* env_width = std::getenv("LP_NATIVE_VECTOR_WIDTH");
    if (!env_width || std::string(env_width) != std::to_string(o.vector_width)) {
        std::fprintf(stderr, "quadshade-bench-throughput --peer-only: LP_NATIVE_VECTOR_WIDTH must be %d (the parent "
                             "bench sets it), found %s\n", o.vector_width, env_width ? env_width : "none");
        return 2;
    }
    qs::Scene scene = qs::load_scene(o.figure ? kFigure : kPlane);
    const int w = o.figure ? scene.width : o.size, h = o.figure ? scene.height : o.size;
    const auto s0 = Clock::now();
    auto context = qs::create_osmesa_context(w, h, qs::GlDriver::Llvmpipe, o.threads);
    qs::GlSceneRenderer gl(scene, {w, h, {}, o.figure ? "" : o.shader, {}}, *context, fs::path(o.glsl));
    gl.draw();  // the first frame compiles llvmpipe's code
    qs::bench::PeerReport report;
    report.setup_ms = ms_since(s0);
    const Stats l = time_frames(o.repeat, [&] { gl.draw(); });
    report.median_ms = l.median;
    report.min_ms = l.min;
    report.max_ms = l.max;
    report.renderer = context->info().renderer;
    std::fputs(qs::bench::format_peer_report(report).c_str(), stdout);
    return 0;
}

// ---- the parent's side ---------------------------------------------------------------------

// llvmpipe at one width on one job, or why there is no measurement.
struct PeerRun {
    int width = 0;
    std::optional<qs::bench::PeerReport> report;  // set when llvmpipe ran at `width`
    std::string missing;  // otherwise: what the table says instead
};

// A child whose report does not parse is this program's fault and fails the bench at the end.
// llvmpipe failing at a width (Mesa 22.3 at 512 bits on an AVX2 CPU crashes on mipmapped
// textures), or not honouring it, is a fact about the peer on this host: the table says so, the
// child's errors go to stderr, and the row is compared with the widths that ran.
int g_unreadable_reports = 0;
int g_rows_without_peer = 0;  // rounds of a row that no width measured: the bench fails

PeerRun run_peer(const Options& o, int width, const std::vector<std::string>& job) {
    std::vector<std::string> argv = {qs::bench::self_executable(), "--peer-only",
                                     "--vector-width", std::to_string(width),
                                     "--threads", std::to_string(o.threads),
                                     "--repeat", std::to_string(o.repeat),
                                     "--glsl", (fs::path(o.out) / "glsl").string()};
    argv.insert(argv.end(), job.begin(), job.end());
    const std::vector<std::string> env = qs::bench::environment_with(
        {"LP_NATIVE_VECTOR_WIDTH=" + std::to_string(width), "GALLIUM_DRIVER=llvmpipe",
         "LP_NUM_THREADS=" + std::to_string(o.threads)});
    PeerRun run{width, std::nullopt, ""};
    std::string what;
    for (const std::string& a : argv) what += (what.empty() ? "" : " ") + a;
    const qs::bench::ChildOutput child = qs::bench::run_child(argv, env);
    if (!child.ok()) {
        std::fprintf(stderr, "\nquadshade-bench-throughput: llvmpipe at %d bits failed (%s): %s\n%s\n", width,
                     child.status().c_str(), what.c_str(), child.err.c_str());
        run.missing = (child.signal ? "llvmpipe crashed: " : "failed: ") + child.status();
        return run;
    }
    try {
        qs::bench::PeerReport report = qs::bench::parse_peer_report(child.out);
        const std::optional<int> bits = qs::bench::vector_bits_of(report.renderer);
        if (bits != width) {
            run.missing = "n/a: llvmpipe ran at " + (bits ? std::to_string(*bits) + " bits" : "an unknown width") +
                          " (" + report.renderer + ")";
            return run;
        }
        run.report = report;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "\nquadshade-bench-throughput: %s: %s\nits stdout:\n%s\n", what.c_str(), e.what(),
                     child.out.c_str());
        ++g_unreadable_reports;
        run.missing = "unreadable report";
    }
    return run;
}

// Whether a report was unreadable or a row's round had llvmpipe at no width: said, and the bench fails.
bool peer_failed() {
    if (g_unreadable_reports == 0 && g_rows_without_peer == 0) return false;
    std::fprintf(stderr, "quadshade-bench-throughput: %d unreadable llvmpipe reports, %d rounds of a row without "
                         "llvmpipe at any width (above)\n", g_unreadable_reports, g_rows_without_peer);
    return true;
}

// The fastest width measured, or nothing.
const PeerRun* fastest(const std::vector<PeerRun>& runs) {
    const PeerRun* best = nullptr;
    for (const PeerRun& r : runs) {
        if (r.report && (!best || r.report->median_ms < best->report->median_ms)) best = &r;
    }
    return best;
}

// "llvmpipe 512-bit": with a note where the CPU has no instructions of that width.
std::string width_title(int width) {
    std::string s = "llvmpipe " + std::to_string(width) + "-bit";
    if (width >= 512 && !__builtin_cpu_supports("avx512f")) s += " (no AVX-512 on this CPU: 256-bit halves)";
    return s;
}

// What the specialised pipeline keeps for a shader, in words; the depth buffer is the frame's
// (the plane's two triangles do not overlap: none).
std::string needs_of(const char* shader, const qs::RenderStats& frame) {
    const qs::Program* p = qs::find_program(shader);
    if (!p) return "?";
    const qs::Needs& n = p->info().needs;
    std::string s = n.derivatives ? "quads" : "per pixel";
    s += frame.depth_buffer ? ", depth" : ", no depth";
    s += n.texture ? ", texture" : "";
    return s;
}

// The median over rounds with its unit, then the range and a note: "2.07x (1.87-2.46; 256 bits)".
std::string over_rounds(const char* fmt, const std::vector<double>& values, const char* unit = "",
                        const std::string& note = "") {
    if (values.empty()) return "-";
    const Stats s = stats_of(values);
    return format(fmt, s.median) + unit + " (" + format(fmt, s.min) + "-" + format(fmt, s.max) +
           (note.empty() ? "" : "; " + note) + ")";
}

// A row's llvmpipe runs at one width over the rounds: its frame times, or what the table says
// instead where a round did not measure it.
std::string peer_cell(const std::vector<const PeerRun*>& runs, const std::function<double(double)>& of_ms, const char* fmt) {
    std::vector<double> values;
    for (const PeerRun* r : runs) {
        if (!r->report) return r->missing;
        values.push_back(of_ms(r->report->median_ms));
    }
    return over_rounds(fmt, values);
}

// "256 bits", or "256/512 bits" when the faster width changed between rounds.
std::string widths_named(std::vector<int> widths) {
    std::sort(widths.begin(), widths.end());
    widths.erase(std::unique(widths.begin(), widths.end()), widths.end());
    std::string s;
    for (int w : widths) s += (s.empty() ? "" : "/") + std::to_string(w);
    return s + " bits";
}

// The renderers Figure 1.1's frame is timed with.
struct FigureMode {
    const char* name;
    qs::Backend backend;
    qs::Derivatives rule;
    const char* rule_name;
};
constexpr FigureMode kFigureModes[] = {
    {"quadshade rasterizer", qs::Backend::Rasterizer, qs::Derivatives::Fine, "fine quads"},
    {"quadshade rasterizer", qs::Backend::Rasterizer, qs::Derivatives::Analytic, "Dual2, plane derivatives"},
    {"quadshade ray caster", qs::Backend::RayCaster, qs::Derivatives::Fine, "fine ray quads"},
    {"quadshade ray caster", qs::Backend::RayCaster, qs::Derivatives::Analytic, "Dual2, ray differentials"}};
constexpr std::size_t kFigureModeCount = std::size(kFigureModes);

// A renderer of the frame, set up once, and its median per round.
struct TimedRenderer {
    std::unique_ptr<qs::SceneRenderer> renderer;
    qs::Framebuffer fb;
    double setup = 0;
    std::vector<double> ms;  // per round
};

// The rounds: every renderer, llvmpipe at each width, then every renderer again in reverse
// order. llvmpipe's runs, [round][width].
std::vector<std::vector<PeerRun>> time_figure(const Options& o, std::vector<TimedRenderer>& timed) {
    std::vector<std::vector<PeerRun>> peers;  // [round][width]
    for (int round = 0; round < o.rounds; ++round) {
        std::fprintf(stderr, "\rround %d/%d Figure 1.1 ...        ", round + 1, o.rounds);
        // Every renderer before llvmpipe and again after it, in reverse order: each one's frames
        // are centred on llvmpipe's.
        std::vector<std::vector<double>> frames(kFigureModeCount);
        auto time_mode = [&](std::size_t i) {
            TimedRenderer& t = timed[i];
            time_frames_into(frames[i], o.repeat, [&] { t.renderer->render_into(t.fb, std::nullopt); });
        };
        for (std::size_t i = 0; i < kFigureModeCount; ++i) time_mode(i);
        peers.emplace_back();
        for (int width : o.widths) peers.back().push_back(run_peer(o, width, {"--figure"}));
        if (!fastest(peers.back())) ++g_rows_without_peer;
        for (std::size_t i = kFigureModeCount; i-- > 0;) time_mode(i);
        for (std::size_t i = 0; i < kFigureModeCount; ++i) timed[i].ms.push_back(stats_of(frames[i]).median);
    }
    return peers;
}

// The frame's table: each renderer's time, set-up and speedup against llvmpipe at its best; the
// ray caster's time against the rasterizer's; llvmpipe at each width.
std::string figure_table(const Options& o, const std::vector<TimedRenderer>& timed,
                         const std::vector<std::vector<PeerRun>>& peers) {
    const auto& modes = kFigureModes;
    auto rasterizer_with = [&](qs::Derivatives rule) {
        std::size_t i = 0;
        while (modes[i].backend != qs::Backend::Rasterizer || modes[i].rule != rule) ++i;
        return i;
    };
    std::vector<int> best_widths;
    for (const std::vector<PeerRun>& round : peers) {
        if (const PeerRun* best = fastest(round)) best_widths.push_back(best->width);
    }

    std::ostringstream md;
    md << "| renderer | derivatives | ms per frame | set-up ms | of which BVH build ms | speedup against llvmpipe at its "
          "best (goal >= 2) | time against the rasterizer's, same derivatives (goal <= 1.5) |\n|---|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < kFigureModeCount; ++i) {
        std::vector<double> speedup, against_raster;
        for (int r = 0; r < o.rounds; ++r) {
            if (const PeerRun* best = fastest(peers[std::size_t(r)])) speedup.push_back(best->report->median_ms / timed[i].ms[std::size_t(r)]);
            if (modes[i].backend == qs::Backend::RayCaster) {
                against_raster.push_back(timed[i].ms[std::size_t(r)] / timed[rasterizer_with(modes[i].rule)].ms[std::size_t(r)]);
            }
        }
        md << format("| %s | %s | ", modes[i].name, modes[i].rule_name) << over_rounds("%.1f", timed[i].ms)
           << format(" | %.1f | %.1f | ", timed[i].setup, 1e3 * timed[i].renderer->bvh_build_seconds())
           << over_rounds("%.2f", speedup, "x", widths_named(best_widths)) << " | "
           << over_rounds("%.2f", against_raster, "x") << " |\n";
    }
    for (std::size_t w = 0; w < o.widths.size(); ++w) {
        std::vector<const PeerRun*> runs;
        std::vector<double> setups;
        for (const std::vector<PeerRun>& round : peers) {
            runs.push_back(&round[w]);
            if (round[w].report) setups.push_back(round[w].report->setup_ms);
        }
        md << format("| OSMesa %s | fine quads | ", width_title(o.widths[w]).c_str())
           << peer_cell(runs, [](double ms) { return ms; }, "%.1f") << " | "
           << (setups.empty() ? std::string("-") : format("%.0f (context, GLSL compile)", stats_of(setups).median))
           << " | - | - | - |\n";
    }
    return md.str();
}

// Figure 1.1, one frame: the rasterizer and the ray caster (quad derivatives and ray
// differentials) next to llvmpipe at each width, with the ray caster's one-off BVH build apart.
// Each round times every renderer in turn and then llvmpipe; every ratio is taken within a
// round, and the table gives its median over the rounds with their range.
std::string figure_frames(const Options& o) {
    qs::Scene scene = qs::load_scene(kFigure);
    std::vector<TimedRenderer> timed(kFigureModeCount);
    for (std::size_t i = 0; i < kFigureModeCount; ++i) {
        qs::FrameRequest req;
        req.backend = kFigureModes[i].backend;
        req.shading.derivatives = kFigureModes[i].rule;
        req.shading.threads = o.threads;
        const auto s0 = Clock::now();
        timed[i].renderer = std::make_unique<qs::SceneRenderer>(scene, req);
        timed[i].setup = ms_since(s0);
    }
    const std::vector<std::vector<PeerRun>> peers = time_figure(o, timed);
    return figure_table(o, timed, peers);
}

// One Table 1.1 row at one size, measured once per round.
struct RowSeries {
    const Row* row;
    int size;
    std::string needs;
    std::vector<Stats> quadshade, general;   // per round
    std::vector<std::vector<PeerRun>> peers;  // [round][width]
};

void measure_round(const Options& o, qs::Scene& scene, RowSeries& s) {
    qs::FrameRequest req;
    req.width = req.height = s.size;
    req.shader_override = s.row->shader;
    req.shading.threads = o.threads;
    qs::Framebuffer fb;
    qs::SceneRenderer renderer(scene, req);
    if (s.needs.empty()) {
        qs::RenderStats frame;
        renderer.render_into(fb, std::nullopt, &frame);
        s.needs = needs_of(s.row->shader, frame);
    }
    // The same frame through the general path: quads with helper lanes and a depth buffer
    // whatever the shader needs.
    qs::FrameRequest general_req = req;
    general_req.raster.force_general_path = true;
    qs::SceneRenderer general(scene, general_req);
    // Both before llvmpipe and again after it, in reverse order: each one's frames are centred on
    // llvmpipe's.
    std::vector<double> quadshade_ms, general_ms;
    auto specialised_frame = [&] { renderer.render_into(fb, std::nullopt); };
    auto general_frame = [&] { general.render_into(fb, std::nullopt); };
    time_frames_into(quadshade_ms, o.repeat, specialised_frame);
    time_frames_into(general_ms, o.repeat, general_frame);
    s.peers.emplace_back();
    for (int w : o.widths) s.peers.back().push_back(run_peer(o, w, {"--size", std::to_string(s.size), "--shader", s.row->shader}));
    if (!fastest(s.peers.back())) ++g_rows_without_peer;
    time_frames_into(general_ms, o.repeat, general_frame);
    time_frames_into(quadshade_ms, o.repeat, specialised_frame);
    s.quadshade.push_back(stats_of(quadshade_ms));
    s.general.push_back(stats_of(general_ms));
}

// One row's lines of throughput.csv, throughput.md and specialisation.md, over its rounds.
void tabulate(const Options& o, const RowSeries& s, std::ostream& csv, std::ostream& md, std::ostream& special) {
    const double frags = double(s.size) * s.size * 1e-3;  // per ms -> Mfrag/s
    std::vector<double> q_rate, q_ms, g_ms, saving, speedup;
    std::vector<int> best_widths;
    for (int r = 0; r < o.rounds; ++r) {
        const Stats& q = s.quadshade[std::size_t(r)];
        const Stats& g = s.general[std::size_t(r)];
        q_rate.push_back(frags / q.median), q_ms.push_back(q.median), g_ms.push_back(g.median);
        saving.push_back(100.0 * (1.0 - q.median / g.median));
        csv << s.row->shader << "," << s.size << "," << o.threads << "," << r + 1 << "," << q.median << "," << q.min
            << "," << q.max;
        for (const PeerRun& p : s.peers[std::size_t(r)]) {
            if (p.report) {
                csv << "," << p.report->median_ms << "," << p.report->min_ms << "," << p.report->max_ms << ","
                    << p.report->setup_ms;
            } else {
                csv << ",,,,";
            }
        }
        if (const PeerRun* best = fastest(s.peers[std::size_t(r)])) {
            const double lm = frags / best->report->median_ms;
            speedup.push_back(frags / q.median / lm);
            best_widths.push_back(best->width);
            csv << "," << best->width << "," << frags / q.median << "," << lm << "," << speedup.back() << "\n";
        } else {
            csv << ",," << frags / q.median << ",,\n";
        }
    }
    special << format("| %s | %d | %s | ", s.row->book_name, s.size, s.needs.c_str()) << over_rounds("%.2f", q_ms)
            << " | " << over_rounds("%.2f", g_ms) << " | " << over_rounds("%.0f", saving, "%") << " |\n";
    md << format("| %s | %d | ", s.row->book_name, s.size) << over_rounds("%.0f", q_rate);
    std::string setups;
    for (std::size_t w = 0; w < o.widths.size(); ++w) {
        std::vector<const PeerRun*> runs;
        std::vector<double> setup;
        for (const std::vector<PeerRun>& round : s.peers) {
            runs.push_back(&round[w]);
            if (round[w].report) setup.push_back(round[w].report->setup_ms);
        }
        md << " | " << peer_cell(runs, [&](double ms) { return frags / ms; }, "%.0f");
        setups += (w ? " / " : "") + (setup.empty() ? std::string("-") : format("%.0f", stats_of(setup).median));
    }
    md << " | " << over_rounds("%.2f", speedup, "x", widths_named(best_widths));
    md << format(" | %s | %d / %d / %d / %d |\n", setups.c_str(), s.row->book[0], s.row->book[1], s.row->book[2],
                 s.row->book[3]);
}

int run_throughput(const Options& o) {
    std::vector<RowSeries> series;
    for (int size : o.sizes) {
        for (const Row& row : kRows) {
            if (o.shaders.empty() || std::find(o.shaders.begin(), o.shaders.end(), row.shader) != o.shaders.end()) {
                series.push_back({&row, size, "", {}, {}, {}});
            }
        }
    }
    // Each round measures every row in turn, so that a round's ratios come from the same minutes
    // and the rounds from different ones.
    qs::Scene scene = qs::load_scene(kPlane);
    for (int round = 0; round < o.rounds; ++round) {
        for (RowSeries& s : series) {
            std::fprintf(stderr, "\rround %d/%d %-16s %4dx%-4d ...", round + 1, o.rounds, s.row->shader, s.size, s.size);
            measure_round(o, scene, s);
        }
    }

    const fs::path out = o.out;
    std::ofstream csv(out / "throughput.csv");
    csv << "shader,size,threads,round,quadshade_ms_median,quadshade_ms_min,quadshade_ms_max";
    for (int w : o.widths) {
        csv << ",llvmpipe" << w << "_ms_median,llvmpipe" << w << "_ms_min,llvmpipe" << w << "_ms_max,llvmpipe" << w
            << "_setup_ms";
    }
    csv << ",best_width,quadshade_mfrags,llvmpipe_best_mfrags,speedup\n";
    std::ostringstream md;
    md << "| shader | size | quadshade Mfrag/s";
    for (int w : o.widths) md << " | " << width_title(w) << " Mfrag/s";
    md << " | speedup against the faster llvmpipe (goal >= 2) | llvmpipe set-up ms";
    for (std::size_t i = 0; i < o.widths.size(); ++i) md << (i ? " / " : " (") << o.widths[i];
    md << ") | 2011 GPUs: 9600M / HD6310 / HD4850 / GTX260 |\n|---|---|---|";
    for (std::size_t i = 0; i < o.widths.size(); ++i) md << "---|";
    md << "---|---|---|\n";
    std::ostringstream special;
    special << "| shader | size | what the shader needs | specialised ms | general path ms | saving |\n"
               "|---|---|---|---|---|---|\n";
    for (const RowSeries& s : series) tabulate(o, s, csv, md, special);
    std::fprintf(stderr, "\r%50s\r", "");
    std::ofstream(out / "throughput.md") << md.str();
    std::printf("%d threads; each cell the median over %d rounds of each round's median of %d frames (quadshade's "
                "of %d, half before llvmpipe's and half after) (min-max over rounds), a round measuring every row in turn; "
                "speedups per round against that round's faster llvmpipe; float RGBA target; llvmpipe in a child "
                "process per vector width\n\n%s",
                o.threads, o.rounds, o.repeat, 2 * o.repeat, md.str().c_str());
    std::ofstream(out / "specialisation.md") << special.str();
    std::printf("\nLeaving out what a shader does not need (ms per frame, %d threads, median over rounds): the "
                "specialised pipeline against the general one (quads with helper lanes, depth buffer)\n\n%s",
                o.threads, special.str().c_str());
    if (o.shaders.empty()) {
        const std::string figure = figure_frames(o);
        std::fprintf(stderr, "\r%50s\r", "");
        std::ofstream(out / "figure-1.1-frame.md") << figure;
        std::printf("\nFigure 1.1 at 1264x400, %d threads, median over %d rounds of each round's median of %d frames "
                    "(quadshade's of %d, half before llvmpipe's and half after) (min-max over rounds); ratios per round\n\n%s",
                    o.threads, o.rounds, o.repeat, 2 * o.repeat, figure.c_str());
    }
    return peer_failed() ? 1 : 0;
}

// Seconds of CPU this process has used, all its threads.
double process_cpu_seconds() {
    rusage u{};
    ::getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// quadshade alone on the noise rows at several thread counts: each round times every shader at
// every count in turn, so a round's ratios come from the same minutes. The cores each count
// actually got (CPU time over wall time) tell a scheduler that does not scale from a shared host
// that did not give the process its cores.
int run_scaling(const Options& o) {
    struct Series {
        const Row* row;
        int size;
        std::vector<std::vector<double>> ms;     // [thread count][round]: median ms of the round
        std::vector<std::vector<double>> cores;  // [thread count][round]: CPU time over wall time
    };
    std::vector<Series> series;
    for (int size : o.sizes) {
        for (const Row& row : kRows) {
            const bool chosen = o.shaders.empty() ? row.noise
                                                  : std::find(o.shaders.begin(), o.shaders.end(), row.shader) != o.shaders.end();
            if (chosen) series.push_back({&row, size, std::vector<std::vector<double>>(o.scaling_threads.size()),
                                          std::vector<std::vector<double>>(o.scaling_threads.size())});
        }
    }
    qs::Scene scene = qs::load_scene(kPlane);
    for (int round = 0; round < o.rounds; ++round) {
        for (Series& s : series) {
            for (std::size_t i = 0; i < o.scaling_threads.size(); ++i) {
                std::fprintf(stderr, "\rround %d/%d %-16s %4d ...", round + 1, o.rounds, s.row->shader,
                             o.scaling_threads[i]);
                qs::FrameRequest req;
                req.width = req.height = s.size;
                req.shader_override = s.row->shader;
                req.shading.threads = o.scaling_threads[i];
                qs::SceneRenderer renderer(scene, req);
                qs::Framebuffer fb;
                const double cpu0 = process_cpu_seconds();
                const auto t0 = Clock::now();
                s.ms[i].push_back(time_frames(o.repeat, [&] { renderer.render_into(fb, std::nullopt); }).median);
                s.cores[i].push_back((process_cpu_seconds() - cpu0) / (1e-3 * ms_since(t0)));
            }
        }
    }
    std::fprintf(stderr, "\r%50s\r", "");
    // Each cell: the median over rounds (min-max); speedups are per round, each thread count
    // against the one before it (2 against 1, 8 against 2).
    auto threads = [](int t) { return std::to_string(t) + (t == 1 ? " thread" : " threads"); };
    std::ostringstream md;
    md << "| shader | size";
    for (int t : o.scaling_threads) md << " | " << threads(t) << " ms";
    for (std::size_t i = 1; i < o.scaling_threads.size(); ++i) {
        md << " | " << threads(o.scaling_threads[i]) << " vs " << o.scaling_threads[i - 1];
    }
    md << " | cores used (CPU time / wall time)";
    for (std::size_t i = 0; i < o.scaling_threads.size(); ++i) md << (i ? " / " : ": ") << o.scaling_threads[i];
    md << " |\n|---|---|";
    for (std::size_t i = 0; i < 2 * o.scaling_threads.size(); ++i) md << "---|";
    md << "\n";
    for (const Series& s : series) {
        md << format("| %s | %d", s.row->book_name, s.size);
        for (const std::vector<double>& ms : s.ms) {
            const Stats st = stats_of(ms);
            md << format(" | %.2f (%.2f-%.2f)", st.median, st.min, st.max);
        }
        for (std::size_t i = 1; i < s.ms.size(); ++i) {
            std::vector<double> ratio;
            for (int r = 0; r < o.rounds; ++r) ratio.push_back(s.ms[i - 1][r] / s.ms[i][r]);
            const Stats st = stats_of(ratio);
            md << format(" | %.2fx (%.2f-%.2f)", st.median, st.min, st.max);
        }
        for (std::size_t i = 0; i < s.cores.size(); ++i) md << format(i ? " / %.2f" : " | %.2f", stats_of(s.cores[i]).median);
        md << " |\n";
    }
    std::ofstream(fs::path(o.out) / "scaling.md") << md.str();
    std::printf("quadshade alone, ms per frame: median over %d rounds of each round's median of %d frames "
                "(min-max over rounds); speedups per round, each thread count against the one before (this host: %u hardware threads)\n\n%s",
                o.rounds, o.repeat, std::thread::hardware_concurrency(), md.str().c_str());
    return 0;
}


// A row's GLSL run another way than its hand translation, and what that way is held to.
struct TwinWay {
    const char* name;  // "interpreter"
    const char* made;  // what making the twin from the GLSL is: "first image", "compile"
    const char* file;  // the table's file in --out
    std::string (*make)(const Row& row, int size);  // the twin's shader name
    bool (*goal_met)(const std::vector<double>& row_ratios);  // ratios: twin time / hand time
    const char* goal;
    bool against_llvmpipe = false;  // each row also beside llvmpipe at its best width, to be >= 2x as fast
};

// The immediate way: the interpreter (render/glsl_shaders.h) within 4x of the translation's frame
// time by the median over the rows.
const TwinWay kInterpreter{
    "interpreter", "first image", "interpreter.md",
    [](const Row& row, int size) {
        // What a user waits for before the first picture: the front end, LLVM's compile of the
        // blocks the frame runs (at its first batch), and the frame.
        const std::string twin = qs::interpreted_twin(row.shader);
        qs::Scene scene = qs::load_scene(kPlane);
        qs::FrameRequest req;
        req.width = req.height = size;
        req.shader_override = twin;
        qs::render_frame(scene, req);
        return twin;
    },
    [](const std::vector<double>& r) { return stats_of(r).median <= 4.0; }, "the median <= 4x"};

// The compiled way: the front end's generated translation (render/compiled_glsl.h), compiled for a
// render's modes into the plugin cache where it lacks it, at >= 0.9 of the hand translation's
// rate by the median over the rows and none below 0.75 (times: <= 1/0.9 and 1/0.75).
const TwinWay kGenerated{
    "generated translation", "compile", "generated.md",
    [](const Row& row, int) {
        const qs::Program& hand = *qs::find_program(row.shader);
        const qs::frontend::GlslSource frag{std::string(row.shader) + ".frag", qs::glsl_source(hand, false)};
        const qs::frontend::GlslSource vert{std::string(row.shader) + ".vert", qs::glsl_source(hand, true)};
        const qs::Program* compiled =
            qs::compiled_glsl_program(frag, vert, "generated " + std::string(row.shader), qs::GlslWay::Compile,
                                      qs::modes_for(hand.info().needs, qs::ShadeRequest{}));
        if (!compiled) throw std::runtime_error(std::string(row.shader) + ": its GLSL did not compile to a plugin");
        return std::string(compiled->info().name);
    },
    [](const std::vector<double>& r) {
        return stats_of(r).median <= 1 / 0.9 && *std::max_element(r.begin(), r.end()) <= 1 / 0.75;
    },
    "the median rate >= 0.9 of the hand translation's, none below 0.75, and every row >= 2x llvmpipe at its best width",
    true};

// A Table 1.1 row at one size, its twin and their times round by round.
struct TwinSeries {
    const Row* row;
    int size;
    std::string twin;
    double make_ms = 0;
    std::size_t lines = 0;
    std::vector<double> hand, twin_ms;  // per round: median ms
    std::vector<double> llvmpipe_ms;    // per round: llvmpipe's at its fastest width (against_llvmpipe)
};

// Each chosen row's twin made `way`, timed.
std::vector<TwinSeries> make_twins(const Options& o, const TwinWay& way) {
    std::vector<TwinSeries> series;
    for (int size : o.sizes) {
        for (const Row& row : kRows) {
            if (!o.shaders.empty() && std::find(o.shaders.begin(), o.shaders.end(), row.shader) == o.shaders.end()) continue;
            TwinSeries s{&row, size, "", 0, 0, {}, {}, {}};
            const auto t0 = Clock::now();
            s.twin = way.make(row, size);
            s.make_ms = ms_since(t0);
            const std::string text = qs::glsl_source(*qs::find_program(row.shader), false);
            s.lines = std::size_t(std::count(text.begin(), text.end(), '\n'));
            series.push_back(std::move(s));
        }
    }
    return series;
}

// The rounds: in each, every series' hand translation and twin in turn (and llvmpipe, where the
// way is measured against it).
void time_twins(const Options& o, const TwinWay& way, std::vector<TwinSeries>& series) {
    qs::Scene scene = qs::load_scene(kPlane);
    for (int round = 0; round < o.rounds; ++round) {
        for (TwinSeries& s : series) {
            std::fprintf(stderr, "\rround %d/%d %-16s %4d ...", round + 1, o.rounds, s.row->shader, s.size);
            if (way.against_llvmpipe) {
                std::vector<PeerRun> runs;
                for (int w : o.widths) runs.push_back(run_peer(o, w, {"--size", std::to_string(s.size), "--shader", s.row->shader}));
                const PeerRun* best = fastest(runs);
                if (!best) ++g_rows_without_peer;
                s.llvmpipe_ms.push_back(best ? best->report->median_ms : std::nan(""));  // one a round
            }
            auto time_shader = [&](const std::string& shader) {
                qs::FrameRequest req;
                req.width = req.height = s.size;
                req.shader_override = shader;
                req.shading.threads = o.threads;
                qs::SceneRenderer renderer(scene, req);
                qs::Framebuffer fb;
                return time_frames(o.repeat, [&] { renderer.render_into(fb, std::nullopt); }).median;
            };
            // Alternating which goes first, so that neither always meets a warmer machine.
            if (round % 2 == 0) {
                s.hand.push_back(time_shader(s.row->shader));
                s.twin_ms.push_back(time_shader(s.twin));
            } else {
                s.twin_ms.push_back(time_shader(s.twin));
                s.hand.push_back(time_shader(s.row->shader));
            }
        }
    }
    std::fprintf(stderr, "\r%50s\r", "");
}

// The way's table, one line per series; `met`: whether the way's goal (and twice llvmpipe's
// speed, where measured against it) is met.
std::string twins_table(const Options& o, const TwinWay& way, const std::vector<TwinSeries>& series, bool& met) {
    std::ostringstream md;
    md << format("| shader | size | GLSL lines | %s ms | translation ms | %s ms | %s / translation |", way.made,
                 way.name, way.name)
       << (way.against_llvmpipe ? " llvmpipe ms (best width) | speedup over llvmpipe |\n|---|---|---|---|---|---|---|---|---|\n"
                                : "\n|---|---|---|---|---|---|---|\n");
    std::vector<double> row_ratios;
    bool twice_llvmpipe = true;
    for (const TwinSeries& s : series) {
        std::vector<double> ratio, speedup;
        for (int r = 0; r < o.rounds; ++r) ratio.push_back(s.twin_ms[std::size_t(r)] / s.hand[std::size_t(r)]);
        const Stats h = stats_of(s.hand), t = stats_of(s.twin_ms), q = stats_of(ratio);
        row_ratios.push_back(q.median);
        md << format("| %s | %d | %zu | %.1f | %.2f (%.2f-%.2f) | %.2f (%.2f-%.2f) | %.2fx (%.2f-%.2f) |", s.row->book_name, s.size,
                     s.lines, s.make_ms, h.median, h.min, h.max, t.median, t.min, t.max, q.median, q.min, q.max);
        if (way.against_llvmpipe) {
            // Each round's llvmpipe against the same round's generated translation; a round
            // without llvmpipe fails the bench below.
            std::vector<double> measured;
            for (std::size_t r = 0; r < s.llvmpipe_ms.size(); ++r) {
                if (std::isnan(s.llvmpipe_ms[r])) continue;
                measured.push_back(s.llvmpipe_ms[r]);
                speedup.push_back(s.llvmpipe_ms[r] / s.twin_ms[r]);
            }
            md << " " << over_rounds("%.2f", measured) << " | " << over_rounds("%.2f", speedup, "x") << " |";
            twice_llvmpipe = twice_llvmpipe && !speedup.empty() && stats_of(speedup).median >= 2.0;
        }
        md << "\n";
    }
    met = way.goal_met(row_ratios) && twice_llvmpipe;
    md << format("\nBy the median over the rows: the %s takes %.2fx the translation's time, %.2fx at most (goal: %s: %s).\n",
                 way.name, stats_of(row_ratios).median, *std::max_element(row_ratios.begin(), row_ratios.end()),
                 way.goal, met ? "met" : "not met");
    return md.str();
}

// Each Table 1.1 row's GLSL run `way` beside its hand translation, the two in turn within each
// round, with the time it took to make the twin (the front end's compile; for a generated
// translation, the plugin's compile where the cache lacked it).
int run_twins(const Options& o, const TwinWay& way) {
    std::vector<TwinSeries> series = make_twins(o, way);
    if (way.against_llvmpipe) qs::export_glsl(fs::path(o.out) / "glsl");  // what llvmpipe compiles
    time_twins(o, way, series);
    bool met = false;
    const std::string md = twins_table(o, way, series, met);
    std::ofstream(fs::path(o.out) / way.file) << md;
    std::printf("Each Table 1.1 row's GLSL run by the %s beside its translation, %d threads, ms per frame: median over %d "
                "rounds of each round's median of %d frames (min-max over rounds)\n\n%s",
                way.name, o.threads, o.rounds, o.repeat, md.c_str());
    if (peer_failed()) return 1;
    return met ? 0 : 3;
}

// The command line's options into `o`: the measurements' and, hidden, the peer child's job.
void add_options(CLI::App& app, Options& o) {
    app.add_option("--threads", o.threads, "threads for quadshade and llvmpipe (LP_NUM_THREADS)")
        ->check(CLI::Range(1, 256));
    app.add_option("--repeat", o.repeat, "frames timed per measurement (median, min-max); quadshade's twice a round, "
                                         "before and after llvmpipe's")->check(CLI::Range(3, 100000));
    app.add_option("--sizes", o.sizes, "square sizes of the Table 1.1 plane (--scaling: 1024)")->delimiter(',')->check(CLI::Range(1, 8192));
    app.add_option("--shaders", o.shaders, "these rows only (no Figure 1.1 frame)")->delimiter(',');
    app.add_option("--widths", o.widths, "llvmpipe vector widths (LP_NATIVE_VECTOR_WIDTH), each in a child process")
        ->delimiter(',')->check(CLI::IsMember({128, 256, 512}));
    app.add_option("--out", o.out, "folder for the tables and CSV");
    app.add_flag("--scaling", o.scaling, "quadshade alone on the noise rows at --scaling-threads (writes scaling.md)");
    app.add_flag("--interpreted", o.interpreted, "each row's GLSL run by the interpreter beside its translation (writes "
                                                 "interpreter.md; exit 3 past the goal)");
    app.add_flag("--generated", o.generated, "each row's GLSL run as its generated translation, compiled into the plugin "
                                             "cache, beside its hand translation (writes generated.md; exit 3 past the goal)");
    app.add_option("--scaling-threads", o.scaling_threads, "thread counts of --scaling, the first the baseline")
        ->delimiter(',')->check(CLI::Range(1, 256));
    app.add_option("--rounds", o.rounds, "rounds, each measuring every row in turn (median and min-max over them)")
        ->check(CLI::Range(1, 1000));
    // The peer child's job, set by the parent (hidden).
    app.add_flag("--peer-only", o.peer_only)->group("");
    app.add_option("--vector-width", o.vector_width)->group("")->check(CLI::IsMember({128, 256, 512}));
    app.add_option("--size", o.size)->group("")->check(CLI::Range(1, 8192));
    app.add_option("--shader", o.shader)->group("");
    app.add_flag("--figure", o.figure)->group("");
    app.add_option("--glsl", o.glsl)->group("");
}

// Whether the options make one run: modes exclusive, each mode's options only with it, the
// peer child's job whole; a message where they do not.
bool options_make_one_run(const Options& o, const CLI::App& app) {
    if (int(o.scaling) + int(o.interpreted) + int(o.generated) > 1) {
        std::fprintf(stderr, "quadshade-bench-throughput: --scaling, --interpreted and --generated are different runs\n");
        return false;
    }
    const bool peer_job = o.vector_width || o.size || !o.shader.empty() || o.figure || !o.glsl.empty();
    if (o.peer_only != peer_job || (o.peer_only && (!o.vector_width || o.glsl.empty() ||
                                                    o.figure == (o.size > 0 || !o.shader.empty()) ||
                                                    (!o.figure && (o.size == 0 || o.shader.empty()))))) {
        std::fprintf(stderr, "quadshade-bench-throughput: --peer-only takes --vector-width, --glsl and either "
                             "--figure or --size and --shader; those options only with --peer-only\n");
        return false;
    }
    // Options of one mode given to the other are refused, not ignored.
    for (const char* opt : {"--widths", "--threads"}) {
        if (o.scaling && app.count(opt) > 0) {
            std::fprintf(stderr, "quadshade-bench-throughput: %s is not an option of --scaling (quadshade alone, at "
                                 "--scaling-threads)\n", opt);
            return false;
        }
    }
    if (o.interpreted && app.count("--widths") > 0) {
        std::fprintf(stderr, "quadshade-bench-throughput: --widths is not an option of --interpreted (quadshade alone)\n");
        return false;
    }
    if (!o.scaling && app.count("--scaling-threads") > 0) {
        std::fprintf(stderr, "quadshade-bench-throughput: --scaling-threads only with --scaling\n");
        return false;
    }
    if (o.peer_only && app.count("--rounds") > 0) {
        std::fprintf(stderr, "quadshade-bench-throughput: --rounds is not an option of --peer-only (the parent runs "
                             "one child per round)\n");
        return false;
    }
    if (o.scaling && o.peer_only) {
        std::fprintf(stderr, "quadshade-bench-throughput: --scaling and --peer-only are two different runs\n");
        return false;
    }
    if (o.scaling && o.scaling_threads.size() < 2) {
        std::fprintf(stderr, "quadshade-bench-throughput: --scaling needs at least two --scaling-threads\n");
        return false;
    }
    for (const std::string& s : o.shaders) {
        if (std::none_of(std::begin(kRows), std::end(kRows), [&](const Row& r) { return s == r.shader; })) {
            std::fprintf(stderr, "quadshade-bench-throughput: --shaders: '%s' is not a Table 1.1 row\n", s.c_str());
            return false;
        }
    }
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    CLI::App app{"quadshade-bench-throughput: Table 1.1's shaders against OSMesa llvmpipe at each vector width, "
                 "and the Figure 1.1 frame"};
    add_options(app, o);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "quadshade-bench-throughput: %s (--help lists the options)\n", e.what());
        return 2;
    }
    if ((o.scaling || o.interpreted || o.generated) && app.count("--sizes") == 0) o.sizes = {1024};
    if (!options_make_one_run(o, app)) return 2;
    try {
        if (o.peer_only) return run_peer_child(o);
        fs::create_directories(o.out);
        if (o.scaling) return run_scaling(o);
        if (o.interpreted) return run_twins(o, kInterpreter);
        if (o.generated) return run_twins(o, kGenerated);
        qs::export_glsl(fs::path(o.out) / "glsl");  // what llvmpipe compiles
        return run_throughput(o);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "quadshade-bench-throughput: %s\n", e.what());
        return 1;
    }
}
