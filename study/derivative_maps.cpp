#include "study/derivative_maps.h"

#include <algorithm>
#include <cmath>

#include "render/frame_image.h"
#include "render/scene_render.h"
#include "shading/catalogue.h"
#include "study/file_name.h"
#include "study/input_derivatives.h"

namespace qs::study {

namespace fs = std::filesystem;

namespace {

// The map program of `shader`'s varying `v`, added to the catalogue once per process.
std::string map_program(const Program& shader, int v) {
    const std::string name = std::string(shader.info().name) + " d(" + varying_name(shader.info(), v) + ")";
    if (!find_program(name)) add_compiled_program(input_derivatives(shader, v, name), "derivative maps", "", "");
    return name;
}

}  // namespace

std::vector<DerivativeMap> input_maps(const std::string& shader) {
    const Program* program = find_program(shader);
    if (!program) throw std::runtime_error("unknown shader '" + shader + "'");
    std::vector<DerivativeMap> maps;
    for (int v = 0; v < program->info().needs.varyings; ++v) {
        if (program->info().needs.flat_varyings & (1u << v)) continue;
        const std::string input = varying_name(program->info(), v);
        maps.push_back({input, "d-" + file_name(input), map_program(*program, v)});
    }
    return maps;
}

std::vector<DerivativeRow> derivative_maps(const Scene& original, const std::vector<DerivativeMap>& maps,
                                           std::optional<double> time, int threads, const fs::path& dir,
                                           const std::string& relative) {
    Scene scene = original;
    scene.clear_color = glm::vec4(0.0f);  // alpha 0 where nothing is drawn: the covered pixels are the others
    const struct {
        const char* name;
        Derivatives rule;
    } rules[] = {{"fine", Derivatives::Fine},
                 {"coarse-lower", Derivatives::CoarseLower},
                 {"coarse-upper", Derivatives::CoarseUpper}};
    std::vector<DerivativeRow> rows;
    for (const DerivativeMap& m : maps) {
        auto render = [&](Derivatives rule) {
            FrameRequest f;
            f.width = scene.width, f.height = scene.height;
            f.time = time;
            f.shader_override = m.program;
            f.shading.derivatives = rule;
            f.shading.threads = threads;
            return colour_image(render_frame(scene, f));
        };
        const Image exact = render(Derivatives::Analytic);
        const std::size_t n = std::size_t(exact.width) * std::size_t(exact.height);
        double largest = 0.0, sum = 0.0;
        std::size_t covered = 0;
        for (std::size_t p = 0; p < n; ++p) {
            if (exact.rgba[p * 4 + 3] <= 0.5f) continue;
            const double dx = exact.rgba[p * 4], dy = exact.rgba[p * 4 + 1];
            largest = std::max({largest, std::abs(dx), std::abs(dy)});
            sum += dx * dx + dy * dy, ++covered;
        }
        const double scale = covered ? std::sqrt(sum / double(covered)) : 0.0;
        // Signed derivatives shown about mid-grey.
        auto shown = [&](const Image& map) {
            Image out = map;
            for (std::size_t p = 0; p < n; ++p) {
                for (int c = 0; c < 2; ++c) {
                    out.rgba[p * 4 + c] = largest > 0 ? float(0.5 + 0.5 * map.rgba[p * 4 + c] / largest) : 0.5f;
                }
                out.rgba[p * 4 + 2] = 0.5f;
            }
            return out;
        };
        const std::string& stem = m.stem;
        write_image(dir / (stem + "-analytic.png"), shown(exact));
        for (const auto& r : rules) {
            const Image map = render(r.rule);
            DerivativeRow row;
            row.input = m.label, row.rule = r.name;
            double sx = 0, sy = 0;
            for (std::size_t p = 0; p < n; ++p) {
                if (exact.rgba[p * 4 + 3] <= 0.5f) continue;
                const double ex = std::abs(double(map.rgba[p * 4]) - exact.rgba[p * 4]);
                const double ey = std::abs(double(map.rgba[p * 4 + 1]) - exact.rgba[p * 4 + 1]);
                sx += ex * ex, sy += ey * ey;
                row.max_dx = std::max(row.max_dx, ex), row.max_dy = std::max(row.max_dy, ey);
            }
            row.rms_dx = covered ? std::sqrt(sx / double(covered)) : 0.0;
            row.rms_dy = covered ? std::sqrt(sy / double(covered)) : 0.0;
            row.scale = scale, row.covered = covered;
            const std::string file = stem + "-" + r.name + ".png", heat = stem + "-" + r.name + "-heat.png";
            write_image(dir / file, shown(map));
            Image a = map, b = exact;  // the heat map over dx and dy only
            for (std::size_t p = 0; p < n; ++p) a.rgba[p * 4 + 2] = b.rgba[p * 4 + 2] = 0.0f;
            write_image(dir / heat, difference_heat_map(a, b, largest > 0 ? float(largest / 4) : 1.0f));
            row.map_image = relative + "/" + file, row.heat_image = relative + "/" + heat;
            row.analytic_image = relative + "/" + stem + "-analytic.png";
            rows.push_back(row);
        }
    }
    return rows;
}

}  // namespace qs::study
