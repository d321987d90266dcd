#include "study/study_memory.h"

#include <algorithm>
#include <set>

#include "core/tile_grid.h"
#include "images/image_io.h"
#include "render/memory_plan.h"
#include "render/scene_render.h"
#include "scenes/scene_files.h"

namespace qs::study {

namespace {

std::string size_text(std::uint64_t w, std::uint64_t h) { return std::to_string(w) + "x" + std::to_string(h); }

}  // namespace

MemoryPlan plan_memory(const Request& r, Scene& scene, const std::vector<Mode>& modes) {
    const std::uint64_t w = std::uint64_t(scene.width), h = std::uint64_t(scene.height), pixels = w * h;
    const std::uint64_t image = pixels * 4 * sizeof(float);  // one RGBA float image at the study's size
    const std::uint64_t png = ImageWriter::conversion_bytes("image.png", int(w), int(h), true);
    // A frame's bytes beside its renderer's geometry: colour and depth, and the undefined-case mask.
    auto frame = [](std::uint64_t n, bool undefined) { return render_working_bytes(n, 0, 0, true, undefined); };

    FrameRequest f;
    f.width = int(w), f.height = int(h);
    std::uint64_t held = 0, loading = 0;
    // A renderer's frame of `rows` rows at the study's size, what it holds beside noted.
    auto measure = [&](Backend backend, const std::string& shader, int rows) {
        f.backend = backend;
        f.shader_override = shader;
        SceneRenderer renderer(scene, f);
        const SceneRenderer::HeldBytes b = renderer.held_bytes();
        held = std::max(held, b.scene + b.textures);
        loading = std::max(loading, b.texture_loading);
        return renderer.frame_bytes(rows);
    };
    // No rows: the vertices and triangles a frame adds beside its pixels, at any size. Each
    // variant's renderer, for the textures it samples.
    std::uint64_t geometry = 0;
    for (const std::string& shader : {r.shaders.shader, r.shaders.unfiltered, r.shaders.alternative}) {
        if (!shader.empty()) geometry = std::max(geometry, measure(Backend::Rasterizer, shader, 0));
    }
    std::uint64_t caster_frame = 0;  // the ray caster renders at the study's size only
    if (std::any_of(modes.begin(), modes.end(), [](const Mode& m) { return m.backend == Backend::RayCaster; })) {
        caster_frame = measure(Backend::RayCaster, r.shaders.shader, int(h));
    }
    // Held throughout: the scene as the study loaded it, one renderer's, and a render's overhead.
    const std::uint64_t base = kRenderOverheadBytes + scene_bytes(scene) + held;

    MemoryPlan plan;
    auto step = [&](std::uint64_t bytes, const std::string& what) {
        if (base + bytes > plan.peak) plan.peak = base + bytes, plan.largest = what;
    };
    const std::string at = " at " + size_text(w, h);
    step(loading, "loading the textures");
    step(geometry + frame(pixels, true) + 3 * image + png, "the float, double and checked frames" + at);
    if (r.derivative_maps) step(geometry + frame(pixels, false) + 6 * image + png, "the derivative maps" + at);

    // The truth: a band of rows of the supersampled frame at a time, summed in double.
    const std::uint64_t k = std::uint64_t(r.truth);
    constexpr std::uint64_t kTruthBandPixels = std::uint64_t(1) << 22;  // as study.cpp's ground truth bands it
    int band_rows = 0;
    const int max_rows = int(std::max<std::uint64_t>(1, kTruthBandPixels / (w * k)));
    for (const RowBand& b : image_bands(int(h * k), f.shading.pairing, max_rows)) {
        band_rows = std::max(band_rows, b.end - b.begin);
    }
    step(geometry + frame(w * k * std::uint64_t(band_rows), false) + 3 * image + png,
         "the truth (" + size_text(w * k, h * k) + " samples, in bands of " + std::to_string(band_rows) + " rows)");

    // Each view holds its truth and llvmpipe's images (one per variant and sampling rate).
    std::set<std::pair<std::string, int>> references;
    if (r.reference) {
        for (const Mode& m : modes) references.emplace(m.shader, m.supersample);
    }
    const std::uint64_t view = image * (1 + references.size());
    for (const Mode& m : modes) {
        const std::uint64_t s = std::uint64_t(m.supersample), samples = pixels * s * s;
        const std::string name =
            "the " + m.name + " mode" + (s > 1 ? " (" + size_text(w * s, h * s) + " samples)" : at);
        const std::uint64_t rendered =
            m.backend == Backend::RayCaster ? caster_frame : geometry + frame(samples, false);
        step(view + rendered + 3 * image + png, name);
        if (r.reference) {
            // llvmpipe's process renders while this one holds the view's images; then its image
            // is read back and filtered.
            step(view + 2 * image + kReferenceBaseBytes + samples * kReferenceBytesPerPixel,
                 name + " in llvmpipe (quadshade-reference's own process)");
            step(view + 3 * image + image_read_bytes(w * s, h * s), name + ": llvmpipe's image read back");
        }
    }
    return plan;
}

void check_memory(const MemoryPlan& plan, std::uint64_t limit) {
    if (limit == 0 || plan.peak <= limit) return;
    throw MemoryError("study: " + plan.largest + " needs " + byte_size_text(plan.peak) + ", more than the " +
                      byte_size_text(limit) +
                      " available (--memory-limit sets it; a smaller --size or --truth, or fewer --modes, need less)");
}

}  // namespace qs::study
