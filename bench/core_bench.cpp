// quadshade-bench-core: the chapter's 2D simplex noise (Listing 1.3) over a 1024x1024 grid on every
// number type, next to a plain loop written directly with std::experimental::simd at native
// width, and the same noise rasterized as a full-screen quad. One run, so the ratios are fair:
//   wide lane type / plain loop       target >= 0.80 (the abstraction costs nothing)
//   rasterized / plain loop, 1 thread target >= 0.85 (rasterization keeps the throughput;
//                                     docs/results.md, The targets across runs)
// The same for an integer-hash shader (PCG value noise) and a loop that breaks per pixel (the
// Mandelbrot set, 100 iterations): each rasterized at >= 0.70 of its plain loop. And GLSL sin
// (llvmpipe's polynomial) against std::experimental::sin, with a nine-tap sine hash rasterized.
// And texture2D's lanes on three samplers (BM_texture2D), for the sampler's own speed. And the
// Figure 1.1 frame with each backend, on one thread and on all cores, and with Dual2 on one
// (BM_frame), so that bench/compare-builds, which runs this program, guards the ray caster and the
// scene path too, and the serial part of a frame (vertex stage, setup, the depth buffer's proof).
// Usage: quadshade-bench-core [Google Benchmark flags]

#include <benchmark/benchmark.h>

#include <cstdio>
#include <experimental/simd>
#include <map>
#include <memory>
#include <string>

#include "shading/catalogue.h"
#include "shading/glsl.h"
#include "shading/noise/simplex2d.h"
#include "shading/shaders/integer_and_loop.h"
#include "raster/rasterizer.h"
#include "render/scene_render.h"
#include "scenes/gltf.h"

namespace {

using namespace qs;
using namespace qs::glsl;
namespace stdx = std::experimental;

constexpr int kSide = 1024;
constexpr int kFragments = kSide * kSide;
constexpr float kScale = 10.0f / kSide;  // st * 10, as the simplex2d shader

template <class F>
F lane_ramp(float start, float step) {
    if constexpr (is_dual2<F>::value) {
        return F(lane_ramp<typename F::value_type>(start, step), typename F::value_type(1.0f), typename F::value_type(0.0f));
    } else if constexpr (is_lanes<F>::value) {
        typename F::value_type v[F::size];
        for (int i = 0; i < F::size; ++i) v[i] = typename F::value_type(start + step * float(i));
        return F::load(v);
    } else {
        return F(start);
    }
}

// A row's coordinate, hidden from the optimizer in each iteration along the row. A fragment
// shader computes its whole function for every fragment; a loop along a row would otherwise
// compute the row's share of it (the hashes of y, y's terms of the skew) once, before the loop,
// and time less arithmetic than any shader does (the PCG loop a third less; the simplex loop
// hardly any). Costs a broadcast per iteration.
inline float per_fragment(float row) {
#if defined(__x86_64__) || defined(__i386__)
    asm volatile("" : "+x"(row));
#else
    asm volatile("" : "+m"(row));
#endif
    return row;
}

// What a benchmark keeps of its sum: lane 0, and of a Dual2 its partials too, so that a
// flattened loop cannot drop their arithmetic.
template <class F>
double kept(const F& acc) {
    if constexpr (is_dual2<F>::value) return double(lane(acc, 0)) + double(lane(acc.dx, 0)) + double(lane(acc.dy, 0));
    else return double(lane(acc, 0));
}

// The benchmarks over number types are flattened, as the renderer's shader instantiations are
// (shading/program_of.h): otherwise GCC stops inlining the noise inside this file's loops and
// passes the lanes through memory, and these rows measure the calls instead of the arithmetic.
template <class F>
[[gnu::flatten]] void BM_simplex2d(benchmark::State& state) {
    constexpr int n = lanes_of<F>();
    static_assert(kSide % n == 0);
    double sink = 0.0;
    for (auto _ : state) {
        F acc(0.0f);
        for (int y = 0; y < kSide; ++y) {
            const float row = (float(y) + 0.5f) * kScale;
            for (int x = 0; x < kSide; x += n) {
                const F px = lane_ramp<F>((float(x) + 0.5f) * kScale, kScale);
                acc += noise::snoise(vec2<F>(px, F(per_fragment(row))));
            }
        }
        sink += kept(acc);
        benchmark::DoNotOptimize(sink);
    }
    state.counters["Mfrag/s"] = benchmark::Counter(double(kFragments) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// The same function written straight on std::experimental::simd, at native width: the yardstick.
using V = stdx::native_simd<float>;
// The shader's mod289, permute and 2 fract(p / 41) - 1 (noise/simplex2d.h): the exact products
// fused where the CPU can.
inline V exact_product_add(V a, V b, V c) {
#if defined(__FMA__)
    return stdx::fma(a, b, c);
#else
    return a * b + c;
#endif
}
inline V mod289(V x) { return exact_product_add(stdx::floor(x * (1.0f / 289.0f)), V(-289.0f), x); }
inline V permute(V x) { return mod289(exact_product_add(x, V(34.0f), V(1.0f)) * x); }
inline V plain_snoise(V vx, V vy) {
    const float Cx = 0.211324865405187f, Cy = 0.366025403784439f, Cz = -0.577350269189626f, Cw = 0.024390243902439f;
    const V s = (vx * Cy + vy * Cy);
    V ix = stdx::floor(vx + s), iy = stdx::floor(vy + s);
    const V t = ix * Cx + iy * Cx;
    const V x0x = vx - ix + t, x0y = vy - iy + t;
    V i1x(0.0f), i1y(1.0f);
    const auto m_ = x0x > x0y;
    stdx::where(m_, i1x) = 1.0f;
    stdx::where(m_, i1y) = 0.0f;
    const V x12x = x0x + Cx - i1x, x12y = x0y + Cx - i1y, x12z = x0x + Cz, x12w = x0y + Cz;
    ix = mod289(ix), iy = mod289(iy);
    const V p0 = permute(permute(iy) + ix), p1 = permute(permute(iy + i1y) + ix + i1x),
            p2 = permute(permute(iy + 1.0f) + ix + 1.0f);
    auto corner = [&](V p, V dx, V dy) {
        V m = stdx::max(0.5f - (dx * dx + dy * dy), V(0.0f));
        m = m * m;
        m = m * m;
        const V xx = exact_product_add(p * Cw - stdx::floor(p * Cw), V(2.0f), V(-1.0f));
        const V h = stdx::abs(xx) - 0.5f;
        const V a0 = xx - stdx::floor(xx + 0.5f);
        m *= 1.79284291400159f - 0.85373472095314f * (a0 * a0 + h * h);
        return m * (a0 * dx + h * dy);
    };
    return 130.0f * (corner(p0, x0x, x0y) + corner(p1, x12x, x12y) + corner(p2, x12z, x12w));
}

void BM_plain_stdx_loop(benchmark::State& state) {
    constexpr int n = int(V::size());
    double sink = 0.0;
    for (auto _ : state) {
        V acc(0.0f);
        const V ramp([](auto i) { return float(i) * kScale; });
        for (int y = 0; y < kSide; ++y) {
            const float row = (float(y) + 0.5f) * kScale;
            for (int x = 0; x < kSide; x += n) acc += plain_snoise(V((float(x) + 0.5f) * kScale) + ramp, V(per_fragment(row)));
        }
        sink += double(acc[0]);
        benchmark::DoNotOptimize(sink);
    }
    state.counters["Mfrag/s"] = benchmark::Counter(double(kFragments) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// ---- the integer hash and the loop with break (shading/shaders/integer_and_loop.h) ---------------
// A shader's fragment function over the grid on number type F, as BM_simplex2d does.
template <class F, class Fragment>
[[gnu::flatten]] void run_grid(benchmark::State& state, Fragment fragment) {
    constexpr int n = lanes_of<F>();
    double sink = 0.0;
    for (auto _ : state) {
        F acc(0.0f);
        for (int y = 0; y < kSide; ++y) {
            const float row = (float(y) + 0.5f) / kSide;
            for (int x = 0; x < kSide; x += n) {
                acc += fragment(vec2<F>(lane_ramp<F>((float(x) + 0.5f) / kSide, 1.0f / kSide), F(per_fragment(row))));
            }
        }
        sink += kept(acc);
        benchmark::DoNotOptimize(sink);
    }
    state.counters["Mfrag/s"] = benchmark::Counter(double(kFragments) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

template <class F>
void BM_pcg_value_noise(benchmark::State& state) {
    run_grid<F>(state, [](const vec2<F>& st) {
        const vec2<F> p = st * 16.0f;
        return 0.5f * noise::value_noise(p) + 0.25f * noise::value_noise(p * 2.0f + 17.0f) +
               0.125f * noise::value_noise(p * 4.0f + 31.0f) + 0.0625f * noise::value_noise(p * 8.0f + 47.0f);
    });
}

template <class F>
void BM_mandelbrot(benchmark::State& state) {
    run_grid<F>(state, [](const vec2<F>& st) {
        FragmentIn<F, shaders::Mandelbrot::VertexStage> in;
        in.gl_FragCoord = vec4<F>(st * float(kSide), 0.0f, 1.0f);  // the pixel centres
        const vec4<F> c = shaders::Mandelbrot::fragment<F>(in, Uniforms{});
        return c.x + c.y + c.z;
    });
}

// The same two functions written straight on std::experimental::simd, at native width.
using U = stdx::rebind_simd_t<std::uint32_t, V>;
using I = stdx::rebind_simd_t<std::int32_t, V>;
inline U plain_pcg_hash(U v) {
    const U state = v * 747796405u + 2891336453u;
    const U word = ((state >> ((state >> 28) + 4u)) ^ state) * 277803737u;
    return (word >> 22) ^ word;
}
inline V plain_cellnoise(V x, V y) {
    const U ux = stdx::static_simd_cast<U>(stdx::static_simd_cast<I>(x) & 0x7FFFFFFF);
    const U uy = stdx::static_simd_cast<U>(stdx::static_simd_cast<I>(y) & 0x7FFFFFFF);
    return stdx::static_simd_cast<V>(plain_pcg_hash(ux + plain_pcg_hash(uy)) & 0xFFFFu) / 65536.0f;
}
inline V plain_mix(V a, V b, V t) { return a * (1.0f - t) + b * t; }
inline V plain_value_noise(V x, V y) {
    const V ix = stdx::floor(x), iy = stdx::floor(y), fx = x - ix, fy = y - iy;
    const V ux = fx * fx * (3.0f - 2.0f * fx), uy = fy * fy * (3.0f - 2.0f * fy);
    const V a = plain_cellnoise(ix, iy), b = plain_cellnoise(ix + 1.0f, iy);
    const V c = plain_cellnoise(ix, iy + 1.0f), d = plain_cellnoise(ix + 1.0f, iy + 1.0f);
    return plain_mix(plain_mix(a, b, ux), plain_mix(c, d, ux), uy);
}
inline V plain_pcg(V s, V t) {
    const V px = s * 16.0f, py = t * 16.0f;
    return 0.5f * plain_value_noise(px, py) + 0.25f * plain_value_noise(px * 2.0f + 17.0f, py * 2.0f + 17.0f) +
           0.125f * plain_value_noise(px * 4.0f + 31.0f, py * 4.0f + 31.0f) +
           0.0625f * plain_value_noise(px * 8.0f + 47.0f, py * 8.0f + 47.0f);
}
// Each lane iterates until it escapes: the lanes still inside are a mask, the loop ends when it
// is empty.
inline V plain_mandelbrot(V s, V t) {
    const V cx = (s * float(kSide)) * (3.0f / 1024.0f) - 2.0f, cy = (t * float(kSide)) * (3.0f / 1024.0f) - 1.5f;
    V x = cx, y = cy, r(0.0f);
    V::mask_type inside(true);
    for (int i = 0; i < 100; ++i) {
        const V nx = x * x + cx - y * y, ny = 2.0f * x * y + cy;
        stdx::where(inside, x) = nx;
        stdx::where(inside, y) = ny;
        stdx::where(inside, r) = nx * nx + ny * ny;
        inside = inside && !(r > 4.0f);
        if (stdx::none_of(inside)) break;
    }
    return x + r * 0.1f + y;
}

template <V (*Function)(V, V)>
void BM_plain(benchmark::State& state) {
    constexpr int n = int(V::size());
    double sink = 0.0;
    for (auto _ : state) {
        V acc(0.0f);
        const V ramp([](auto i) { return float(i) / kSide; });
        for (int y = 0; y < kSide; ++y) {
            const float row = (float(y) + 0.5f) / kSide;
            for (int x = 0; x < kSide; x += n) acc += Function(V((float(x) + 0.5f) / kSide) + ramp, V(per_fragment(row)));
        }
        sink += double(acc[0]);
        benchmark::DoNotOptimize(sink);
    }
    state.counters["Mfrag/s"] = benchmark::Counter(double(kFragments) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// GLSL sin on the lanes (llvmpipe's polynomial, shading/number/sin_cos.h) against the library's
// std::experimental::sin it replaced, on the sine hash's arguments: dot(p, (12.9898, 78.233))
// over p in [0, 128)^2, the range of the OpenGL ES tutorial's 128 tiles.
template <class F>
[[gnu::flatten]] void BM_sin(benchmark::State& state) {
    constexpr int n = lanes_of<F>();
    double sink = 0.0;
    for (auto _ : state) {
        F acc(0.0f);
        for (int y = 0; y < kSide; ++y) {
            const float row = float(y) * (128.0f / kSide) * 78.233f;
            for (int x = 0; x < kSide; x += n) {
                acc += sin(lane_ramp<F>(float(x) * (128.0f / kSide), 128.0f / kSide) * 12.9898f + F(per_fragment(row)));
            }
        }
        sink += kept(acc);
        benchmark::DoNotOptimize(sink);
    }
    state.counters["Mfrag/s"] = benchmark::Counter(double(kFragments) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}
inline V plain_sin(V s, V t) { return stdx::sin(s * (128.0f * 12.9898f) + t * (128.0f * 78.233f)); }

// A full-window square through the whole pipeline: vertex stage, setup, tiles, quads/pixels.
void BM_raster(benchmark::State& state, const char* shader, int threads) {
    const Program* program = find_program(shader);
    static const std::vector<VertexIn> verts = {{{-1, -1, 0}, {0, 0}}, {{1, -1, 0}, {1, 0}}, {{1, 1, 0}, {1, 1}}, {{-1, 1, 0}, {0, 1}}};
    static const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
    DrawCall d{verts, idx, program, {}};
    RasterOptions options;
    options.threads = threads;
    Framebuffer fb;  // reused, as an animation loop does
    for (auto _ : state) {
        rasterize_into(fb, kSide, kSide, glm::vec4(0.0f), std::span<const DrawCall>(&d, 1), options);
        benchmark::DoNotOptimize(fb.rgba.data());
    }
    state.counters["Mfrag/s"] = benchmark::Counter(double(kFragments) * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// ---- the Figure 1.1 frame (render/scene_render.h) -----------------------------------------------
// One frame after another into the same framebuffer, as an animation loop renders them; the ray
// caster's BVH is built before the timing.
// A build without Figure 1.1's shaders (QUADSHADE_SHADER_GROUPS) reports the row as skipped.
void BM_frame(benchmark::State& state, Backend backend, int threads, Derivatives derivatives = Derivatives::Fine) {
    std::unique_ptr<SceneRenderer> renderer;
    static Scene scene;
    try {
        if (scene.objects.empty()) scene = load_scene(QUADSHADE_SOURCE_DIR "/scenes/assets/figure-1.1.gltf");
        FrameRequest request;
        request.backend = backend;
        request.shading.threads = threads;
        request.shading.derivatives = derivatives;
        renderer = std::make_unique<SceneRenderer>(scene, request);
    } catch (const std::exception& e) {
        state.SkipWithError(e.what());
        return;
    }
    Framebuffer fb;
    for (auto _ : state) {
        renderer->render_into(fb, std::nullopt);
        benchmark::DoNotOptimize(fb.rgba.data());
    }
    state.counters["Mpixel/s"] = benchmark::Counter(double(renderer->width()) * renderer->height() * 1e-6,
                                                    benchmark::Counter::kIsIterationInvariantRate);
}

// ---- texture lookups (shading/glsl/texture*.cpp) -----------------------------------------------
// texture2D over the grid, st in [0,1]^2 as on Table 1.1's plane, from a 256x256 texture of random
// texels (the plane's image size): bilinear CLAMP_TO_EDGE as single_texture (8-bit path, no level
// of detail), trilinear REPEAT with mipmaps (one level of detail per quad, two levels), and
// MIRRORED_REPEAT (the float path).
enum class TextureCase { Bilinear, Trilinear, Mirrored };
const sampler2D& bench_texture(TextureCase c) {
    static const std::vector<std::uint8_t> rgba = [] {
        std::vector<std::uint8_t> v(256 * 256 * 4);
        std::uint32_t x = 12345;
        for (auto& b : v) b = std::uint8_t((x = x * 1664525u + 1013904223u) >> 24);
        return v;
    }();
    static const sampler2D bilinear(256, 256, rgba.data(), SamplerState{});
    static const sampler2D trilinear(256, 256, rgba.data(),
                                     SamplerState{.wrap_s = glsl::Wrap::Repeat, .wrap_t = glsl::Wrap::Repeat, .mip = MipFilter::Linear});
    static const sampler2D mirrored(256, 256, rgba.data(),
                                    SamplerState{.wrap_s = glsl::Wrap::MirroredRepeat, .wrap_t = glsl::Wrap::MirroredRepeat});
    return c == TextureCase::Bilinear ? bilinear : c == TextureCase::Trilinear ? trilinear : mirrored;
}
template <class F, TextureCase C>
void BM_texture2D(benchmark::State& state) {
    const sampler2D& tex = bench_texture(C);
    // Trilinear: st * 12 minifies the 256x256 texture, to a level between 1 and 3 (the grid's
    // lanes are not laid out as quads, so the level is only roughly the screen's).
    const float scale = C == TextureCase::Trilinear ? 12.0f : 1.0f;
    run_grid<F>(state, [&](const vec2<F>& st) {
        const vec4<F> c = texture2D(tex, st * scale);
        return c.x + c.y + c.z + c.w;
    });
}

// Table 1.1's textured rows through the whole pipeline on one thread, as BM_raster, from the
// bilinear texture above (the plane's image is 256x256 CLAMP_TO_EDGE LINEAR too), at Table 1.1's
// two sizes: 1024x1024 magnifies the texture 4 times, so a 4x4 block reads one or two texel
// rows; 500x500 about twice, up to three.
void BM_raster_textured(benchmark::State& state, const char* shader, int side) {
    const Program* program = find_program(shader);
    static const std::vector<VertexIn> verts = {{{-1, -1, 0}, {0, 0}}, {{1, -1, 0}, {1, 0}}, {{1, 1, 0}, {1, 1}}, {{-1, 1, 0}, {0, 1}}};
    static const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3};
    DrawCall d{verts, idx, program, {}};
    d.uniforms.teximage = &bench_texture(TextureCase::Bilinear);
    RasterOptions options;
    options.threads = 1;
    Framebuffer fb;
    for (auto _ : state) {
        rasterize_into(fb, side, side, glm::vec4(0.0f), std::span<const DrawCall>(&d, 1), options);
        benchmark::DoNotOptimize(fb.rgba.data());
    }
    state.counters["Mfrag/s"] = benchmark::Counter(double(side) * side * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// Keeps each benchmark's rate so main can print the ratios of this very run.
class RateReporter : public benchmark::ConsoleReporter {
public:
    std::map<std::string, double> rates;
    void ReportRuns(const std::vector<Run>& runs) override {
        for (const Run& r : runs) {
            if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
            auto it = r.counters.find("Mfrag/s");
            if (it != r.counters.end()) rates[r.run_name.function_name + (r.run_name.args.empty() ? "" : "/" + r.run_name.args)] = it->second;
        }
        ConsoleReporter::ReportRuns(runs);
    }
};

}  // namespace

BENCHMARK_TEMPLATE(BM_simplex2d, float)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_simplex2d, double)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_simplex2d, Pixels<float, 16>)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_simplex2d, Quads<float, 4>)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_simplex2d, Dual2<Pixels<float, 16>>)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_plain_stdx_loop)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_raster, constant_color_1thread, "constant_color", 1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_raster, simplex2d_1thread, "simplex2d", 1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_raster, constant_color_all_threads, "constant_color", 0)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_raster, simplex2d_all_threads, "simplex2d", 0)->Unit(benchmark::kMillisecond)->UseRealTime();
// Wall-clock time like the rasterized runs, so that their ratios hold on a host shared with others.
BENCHMARK_TEMPLATE(BM_pcg_value_noise, Pixels<float, 16>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_plain, plain_pcg)->Name("BM_plain_stdx_pcg")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_raster, pcg_value_noise_1thread, "pcg_value_noise", 1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_mandelbrot, Pixels<float, 16>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_plain, plain_mandelbrot)->Name("BM_plain_stdx_mandelbrot")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_raster, mandelbrot_1thread, "mandelbrot", 1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_sin, Pixels<float, 16>)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_plain, plain_sin)->Name("BM_plain_stdx_sin")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_raster, es_smooth9_tiles128_1thread, "es_smooth9_tiles128", 1)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_CAPTURE(BM_frame, figure_1_1_raster_1thread, Backend::Rasterizer, 1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_frame, figure_1_1_raster_all_threads, Backend::Rasterizer, 0)->Unit(benchmark::kMillisecond)->UseRealTime();
#if defined(QUADSHADE_HAS_RAYCAST)
BENCHMARK_CAPTURE(BM_frame, figure_1_1_raycast_1thread, Backend::RayCaster, 1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_frame, figure_1_1_raycast_all_threads, Backend::RayCaster, 0)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif
// Dual2: the rasterizer's plane derivatives, the ray caster's ray differentials.
BENCHMARK_CAPTURE(BM_frame, figure_1_1_raster_dual2_1thread, Backend::Rasterizer, 1, Derivatives::Analytic)->Unit(benchmark::kMillisecond)->UseRealTime();
#if defined(QUADSHADE_HAS_RAYCAST)
BENCHMARK_CAPTURE(BM_frame, figure_1_1_raycast_dual2_1thread, Backend::RayCaster, 1, Derivatives::Analytic)->Unit(benchmark::kMillisecond)->UseRealTime();
#endif

BENCHMARK_TEMPLATE(BM_texture2D, Pixels<float, 16>, TextureCase::Bilinear)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_texture2D, Quads<float, 4>, TextureCase::Bilinear)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_texture2D, Quads<float, 4>, TextureCase::Trilinear)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_texture2D, Quads<float, 4>, TextureCase::Mirrored)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_raster_textured, single_texture_1thread, "single_texture", kSide)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_raster_textured, halftone_1thread, "halftone", kSide)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_raster_textured, single_texture_500_1thread, "single_texture", 500)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_raster_textured, halftone_500_1thread, "halftone", 500)->Unit(benchmark::kMillisecond)->UseRealTime();

int main(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    RateReporter reporter;
    benchmark::RunSpecifiedBenchmarks(&reporter);
    auto rate = [&](const std::string& name) {
        auto it = reporter.rates.find(name);
        return it == reporter.rates.end() ? 0.0 : it->second;
    };
    const double plain = rate("BM_plain_stdx_loop");
    const double wide = rate("BM_simplex2d<Pixels<float, 16>>");
    const double raster1 = rate("BM_raster/simplex2d_1thread");
    if (plain > 0 && wide > 0) {
        std::printf("\nnative simd width: %zu floats\n", stdx::native_simd<float>::size());
        std::printf("Pixels<float,16> / plain std::experimental::simd loop: %.2f (goal >= 0.80) %s\n", wide / plain,
                    wide / plain >= 0.80 ? "MET" : "NOT MET");
    }
    if (plain > 0 && raster1 > 0) {
        std::printf("rasterized simplex2d (1 thread) / plain loop: %.2f (goal >= 0.85) %s\n", raster1 / plain,
                    raster1 / plain >= 0.85 ? "MET" : "NOT MET");
    }
    for (const std::string shader : {"pcg", "mandelbrot"}) {
        const std::string name = shader == "pcg" ? "pcg_value_noise" : shader;
        const double loop = rate("BM_plain_stdx_" + shader);
        const double lanes = rate("BM_" + name + "<Pixels<float, 16>>");
        const double raster = rate("BM_raster/" + name + "_1thread");
        if (loop > 0 && lanes > 0) std::printf("%s: Pixels<float,16> / plain loop: %.2f\n", name.c_str(), lanes / loop);
        if (loop > 0 && raster > 0) {
            std::printf("%s: rasterized (1 thread) / plain loop: %.2f (goal >= 0.70) %s\n", name.c_str(), raster / loop,
                        raster / loop >= 0.70 ? "MET" : "NOT MET");
        }
    }
    const double sin_loop = rate("BM_plain_stdx_sin"), sin_lanes = rate("BM_sin<Pixels<float, 16>>");
    if (sin_loop > 0 && sin_lanes > 0) {
        std::printf("sin: llvmpipe's polynomial on Pixels<float,16> / std::experimental::sin loop: %.2f\n", sin_lanes / sin_loop);
    }
    benchmark::Shutdown();
    return 0;
}
