#pragma once
// `quadshade study`: error against run time for one shader on one scene. For each view
// (study_views.h) and mode (study_modes.h) it renders the shader, timed (the median and range of
// `repeat` frames after warm-up ones), and measures the image's RMS and largest error
//   against the truth: the shader's unfiltered variant where it names one, else the shader
//     itself, rendered at truth x truth samples per pixel in double and box-filtered;
//   against OSMesa llvmpipe running the same GLSL (quadshade-reference, a separate process),
//     supersampled alike for the supersampled modes.
// On each view it also maps the derivatives of the shader's inputs, or of expressions a user
// names (expression_derivatives.h), under each quad rule against the analytic ones
// (derivative_maps.h), and measures its float image against its double one and marks the
// undefined GLSL cases it meets (stability.h). Its memory is planned before it runs
// (study_memory.h).
// It writes, in the output folder, by files/output_file.h's rule: study.csv (one row per view and
// mode), views.csv,
// derivatives.csv (one row per view, input and rule), stability.csv (one per view), the images
// (images/CASE/MODE.png, its heat map against the truth, llvmpipe's, the truth's, the derivative
// maps and the stability images), the Pareto plots (plots/CASE.png, drawn by python3-matplotlib
// where it is installed) and report.html, which holds every image and plot itself.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "study/study_csv.h"
#include "study/study_modes.h"
#include "study/study_views.h"

namespace qs::study {

struct Request {
    std::filesystem::path scene;
    Shaders shaders;
    // Generated views' names or camera files (study_views.h); empty: camera, magnified, minified
    // and grazing, or the camera alone with `frames`.
    std::vector<std::string> views;
    std::vector<int> frames;  // each view at each of these frames (time = frame / fps)
    double fps = 30.0;
    std::vector<std::string> modes;  // empty: every mode
    std::string keep_shader;         // draw only the objects whose material names this shader
    int size = 256;                  // the image's longer side; the scene's aspect is kept
    int truth = 32;                  // samples per pixel along each axis for the truth
    int repeat = 5, threads = 2;
    std::optional<double> time;   // the `time` uniform; default: the scene's
    glm::dvec3 offset{0.0};       // added to the shaders' coordinates (stability.h)
    bool reference = true;        // measure against llvmpipe
    bool derivative_maps = true;  // map the inputs' derivatives under each rule (derivative_maps.h)
    // GLSL expressions whose derivatives are mapped in place of the inputs' (`--derivatives-of`).
    std::vector<std::string> expressions;
    std::filesystem::path output;
    // The case's name in the CSV's `shader` column and the report (default: the shader's).
    std::string label;
};

// Everything about a study that can be checked before it writes anything: its views, modes and
// shaders, the expressions it maps (compiled now, glslang's messages naming --derivatives-of)
// and its memory, planned against `memory_limit` (study_memory.h): returns the plan's peak. Throws
// std::invalid_argument for a request it cannot honour, MemoryError for one that needs more,
// std::runtime_error for a scene or shader that fails.
std::uint64_t check_study(const Request& request, std::uint64_t memory_limit);

// The views a request names, at its frames.
std::vector<View> views_of(const Request& request);

// Runs the study: writes its images, views and GLSL into request.output (an existing folder) and
// adds its rows to `tables` (write_tables writes them), so that several studies share one report.
// Progress on stderr. Throws std::invalid_argument for a request it cannot honour (an unknown view
// or mode, a truth rate the size cannot take), std::runtime_error for a scene, shader or
// reference that fails, OutputError for an output that cannot be written.
void run_study(const Request& request, Tables& tables);

// The files a study reads: its scene and every file the scene names, and the camera files its
// views name with theirs. Throws as loading the scene does.
std::vector<std::filesystem::path> study_inputs(const Request& request);

// Refuses (std::invalid_argument naming both) an output folder where a study would write over
// one of `inputs`: its tables, report.html, or a file in the folders it fills (images/, plots/,
// glsl/, views/).
void refuse_outputs_over(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs);

// Writes report.html (and the plots) from the output folder's study.csv and views.csv.
void write_report(const std::filesystem::path& output);

}  // namespace qs::study
