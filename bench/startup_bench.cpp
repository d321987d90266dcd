// quadshade-bench-startup: what one call of quadshade costs, start-up and all, as a user's script
// sees it: the wall time, CPU time and peak resident memory of whole processes, beside the frame
// time each render reports, and the same for programs that only link one library each
// (quadshade-load-probe-*, load_probe.cpp). Every call runs --runs times, interleaved (run r of
// every call before run r + 1 of any), so that the host's drift over the minutes reaches every
// row alike; a cell is the median with the range. One more run of each under LD_DEBUG=files
// counts the shared objects it loads (the program itself not counted).
//
//   quadshade-bench-startup [--runs N] [--out DIR] [--quadshade PATH]
// Writes DIR/startup.md and prints it; exit 0 whether or not the targets are met. --quadshade
// times another build's quadshade (default: the one beside this program).

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench/child_process.h"

namespace {

namespace fs = std::filesystem;
using qs::bench::ChildOutput;

struct Samples {
    std::vector<double> values;
    double median() const {
        std::vector<double> v = values;
        std::sort(v.begin(), v.end());
        const std::size_t n = v.size();
        return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
    }
    double min() const { return *std::min_element(values.begin(), values.end()); }
    double max() const { return *std::max_element(values.begin(), values.end()); }
};

struct Call {
    std::string label;
    std::vector<std::string> argv;
    bool renders = false;  // prints quadshade's summary line, whose frame time is kept
    // The target, in words and as a test on the medians (wall ms, peak MB, frame ms) or on the
    // median of each run's wall time less its frame time; empty: none.
    std::string target;
    std::function<bool(double wall_ms, double rss_mb, double overhead_ms)> met;
    Samples wall_ms{}, cpu_ms{}, rss_mb{}, frame_ms{}, overhead_ms{};
    int objects = 0;
};

// The frame time of quadshade's summary line ("render 3.1 ms/frame"); -1 when absent.
double frame_ms(const std::string& err) {
    static const std::regex summary(R"(render ([0-9.]+) ms/frame)");
    std::smatch m;
    return std::regex_search(err, m, summary) ? std::stod(m[1]) : -1.0;
}

// The shared objects a run loaded, from the dynamic loader's LD_DEBUG=files trace ("file=NAME [0];",
// NAME a path or a soname, the same object named either way in one trace).
int shared_objects(const std::vector<std::string>& argv) {
    const ChildOutput run = qs::bench::run_child(argv, qs::bench::environment_with({"LD_DEBUG=files"}));
    static const std::regex loaded(R"(file=(\S+) +\[)");
    std::set<std::string> names;
    for (auto it = std::sregex_iterator(run.err.begin(), run.err.end(), loaded); it != std::sregex_iterator(); ++it) {
        names.insert(fs::path((*it)[1].str()).filename().string());  // named by path or by soname
    }
    return int(names.size());
}

std::string load_average() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return one + " " + five + " " + fifteen;
}

std::string cell(const Samples& s, const char* format) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, format, s.median(), s.min(), s.max());
    return buffer;
}

// The calls timed: quadshade's commands on the shipped scenes, OSMesa's reference where it is
// built, and a program linking each optional library alone.
std::vector<Call> startup_calls(const std::string& quadshade, const fs::path& bin, const std::string& out) {
    const fs::path assets = fs::path(QUADSHADE_SOURCE_DIR) / "scenes" / "assets";
    const std::string plane = (assets / "table-1.1-plane.gltf").string();
    std::vector<Call> calls;
    calls.push_back({"`quadshade --help`", {quadshade, "--help"}, false, "<= 20 ms and <= 20 MB",
                     [](double wall, double rss, double) { return wall <= 20.0 && rss <= 20.0; }});
    calls.push_back({"`quadshade shaders` (the catalogue listed)", {quadshade, "shaders"}, false, "", nullptr});
    calls.push_back({"`quadshade render` Table 1.1 plane, 64x64, PNG",
                     {quadshade, "render", plane, "--size", "64x64", "-o", (fs::path(out) / "plane-64.png").string()},
                     true, "<= 60 ms",
                     [](double wall, double, double) { return wall <= 60.0; }});
    calls.push_back({"`quadshade render` Table 1.1 plane, 64x64, OpenEXR",
                     {quadshade, "render", plane, "--size", "64x64", "-o", (fs::path(out) / "plane-64.exr").string()},
                     true, "", nullptr});
    // One reference image, as `quadshade check` has each of its cases rendered: OSMesa's frame,
    // written as OpenEXR. Its frame time is not on a summary line of quadshade's.
    const fs::path reference = fs::path(quadshade).parent_path() / "quadshade-reference";
    const fs::path glsl = QUADSHADE_GLSL_DIR;  // the shaders' GLSL, exported by the build
    if (fs::exists(reference) && fs::exists(glsl)) {
        calls.push_back({"`quadshade-reference` Table 1.1 plane, checker, 64x64, OpenEXR",
                         {reference.string(), plane, "--shader", "checker", "--size", "64x64", "--glsl",
                          glsl.string(), "-o",
                          (fs::path(out) / "reference-64.exr").string()},
                         false, "", nullptr});
    }
    calls.push_back({"`quadshade render` Figure 1.1, 1264x400, PNG",
                     {quadshade, "render", (assets / "figure-1.1.gltf").string(), "-o",
                      (fs::path(out) / "figure-1.1.png").string()},
                     true, "<= frame + 50 ms",
                     [](double, double, double overhead) { return overhead <= 50.0; }});
    calls.push_back({"`quadshade render` two triangles (the plane, constant colour), 1024x1024, PNG",
                     {quadshade, "render", plane, "--shader", "constant_color", "--size", "1024x1024", "-o",
                      (fs::path(out) / "two-triangles.png").string()},
                     true, "", nullptr});
    calls.push_back({"`quadshade render` Figure 1.1, ray cast, 1264x400, PNG",
                     {quadshade, "render", (assets / "figure-1.1.gltf").string(), "--backend", "raycast", "-o",
                      (fs::path(out) / "figure-1.1-raycast.png").string()},
                     true, "", nullptr});
    for (const char* library : {"none", "tbb", "libpng", "openexr", "embree", "osmesa", "openimageio"}) {
        const fs::path probe = bin / (std::string("quadshade-load-probe-") + library);
        if (!fs::exists(probe)) continue;  // not built: that library was not found
        calls.push_back({std::string("a program linking ") +
                             (std::string(library) == "none" ? "no library (the C++ runtime)" : library),
                         {probe.string()}, false, "", nullptr});
    }

    return calls;
}

// Each call `runs` times, interleaved: false, with a message, where one fails.
bool time_calls(std::vector<Call>& calls, int runs) {
    const std::vector<std::string> env = qs::bench::environment_with({});
    for (int r = 0; r < runs; ++r) {
        for (Call& c : calls) {
            const ChildOutput run = qs::bench::run_child(c.argv, env);
            if (!run.ok()) {
                std::fprintf(stderr, "quadshade-bench-startup: %s: %s\n%s", c.label.c_str(), run.status().c_str(),
                             run.err.c_str());
                return false;
            }
            c.wall_ms.values.push_back(1e3 * run.wall_seconds);
            c.cpu_ms.values.push_back(1e3 * run.cpu_seconds);
            c.rss_mb.values.push_back(double(run.peak_rss_bytes) * 1e-6);
            if (c.renders) {
                const double frame = frame_ms(run.err);
                if (frame < 0.0) {
                    std::fprintf(stderr, "quadshade-bench-startup: %s: no summary line\n%s", c.label.c_str(), run.err.c_str());
                    return false;
                }
                c.frame_ms.values.push_back(frame);
                c.overhead_ms.values.push_back(1e3 * run.wall_seconds - frame);
            }
        }
    }
    for (Call& c : calls) c.objects = shared_objects(c.argv);
    return true;
}

// startup.md's table: each call's medians and ranges, and whether it meets its target.
std::string startup_table(const std::vector<Call>& calls, int runs, const std::string& load_before) {
    std::ostringstream md;
    md << "| call | shared objects | wall ms | CPU ms | peak RSS MB | frame ms | wall - frame ms | target |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---|\n";
    for (const Call& c : calls) {
        const bool renders = c.renders;
        std::string target = "-";
        if (c.met) {
            target = c.target + (c.met(c.wall_ms.median(), c.rss_mb.median(), renders ? c.overhead_ms.median() : 0.0)
                                     ? ": met"
                                     : ": **not met**");
        }
        md << "| " << c.label << " | " << c.objects << " | " << cell(c.wall_ms, "%.1f (%.1f-%.1f)") << " | "
           << cell(c.cpu_ms, "%.1f (%.1f-%.1f)") << " | " << cell(c.rss_mb, "%.1f (%.1f-%.1f)") << " | " << (renders ? cell(c.frame_ms, "%.1f (%.1f-%.1f)") : "-")
           << " | " << (renders ? cell(c.overhead_ms, "%.1f (%.1f-%.1f)") : "-") << " | " << target << " |\n";
    }
    md << "\n" << runs << " runs of each call, interleaved; median (range). CPU: user and system time on "
       << "every core. MB: 10^6 bytes. Load average " << load_before << " before, " << load_average() << " after.\n";
    return md.str();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("quadshade-bench-startup: wall time and peak memory of whole quadshade calls and of "
                 "programs linking one library each");
    int runs = 21;
    std::string out = "build/startup";
    app.add_option("--runs", runs, "runs of each call (default 21)")->check(CLI::Range(1, 1000));
    app.add_option("--out", out, "folder for startup.md and the rendered images (default build/startup)");
    const fs::path bin = fs::path(qs::bench::self_executable()).parent_path();
    std::string quadshade = (bin / "quadshade").string();
    app.add_option("--quadshade", quadshade, "the quadshade to time (default: the one beside this program)");
    CLI11_PARSE(app, argc, argv);

    fs::create_directories(out);
    std::vector<Call> calls = startup_calls(quadshade, bin, out);
    const std::string load_before = load_average();
    if (!time_calls(calls, runs)) return 1;
    const std::string md = startup_table(calls, runs, load_before);
    std::ofstream(fs::path(out) / "startup.md") << md;
    std::fputs(md.c_str(), stdout);
    return 0;
}
