// quadshade-bench-batch-width: for every catalogue shader, the time to shade two batches with
// two Program::shade calls and with one Program::shade_pair, in the mode the rasterizer uses for
// it (per pixel, or Fine quads when it takes derivatives). Shaders that declare
// ShaderInfo::wide_batches run the pair as one number of twice the width and should come out
// faster (ratio below 1); the others run it as two calls (ratio about 1). To see whether another
// shader gains, set its flag and run this again.
//
//   quadshade-bench-batch-width [--repeat N] [SHADER...]   (median of N timings, default 15;
//                                                         the named shaders only, if any)

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "shading/catalogue.h"
#include "shading/shade_choice.h"

namespace {

using namespace qs;
using Clock = std::chrono::steady_clock;

volatile float sink;  // keeps the results alive

// Inputs in the range the shaders see on screen, different in every lane and in the two batches.
FragmentBatch batch_at(float offset) {
    FragmentBatch in{};
    for (int i = 0; i < kBatchLanes; ++i) {
        const float x = offset + float(i % 4) + 0.37f * float(i / 4), y = float(i / 4);
        for (int k = 0; k < 4; ++k) in.frag_coord[k][i] = 8.5f + x + float(k) * y;
        for (int v = 0; v < kMaxVaryings; ++v) in.varying[v][i] = 0.05f * x + 0.03f * y + 0.1f * float(v);
    }
    return in;
}

// Nanoseconds per call of `shade_two`, median of `repeat` timings of a loop long enough to time.
template <class ShadeTwo>
double time_ns(int repeat, ShadeTwo shade_two) {
    constexpr int kCalls = 4000;
    std::vector<double> ns;
    for (int r = 0; r < repeat; ++r) {
        const auto start = Clock::now();
        for (int c = 0; c < kCalls; ++c) shade_two();
        ns.push_back(std::chrono::duration<double, std::nano>(Clock::now() - start).count() / kCalls);
    }
    std::nth_element(ns.begin(), ns.begin() + repeat / 2, ns.end());
    return ns[std::size_t(repeat / 2)];
}

}  // namespace

int main(int argc, char** argv) {
    int repeat = 15;
    std::vector<std::string> only;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
            repeat = std::max(1, std::atoi(argv[++i]));
        } else if (argv[i][0] != '-' && find_program(argv[i])) {
            only.emplace_back(argv[i]);
        } else {
            std::fprintf(stderr, "usage: %s [--repeat N] [SHADER...]\n'%s': %s\n", argv[0], argv[i],
                         std::strcmp(argv[i], "--repeat") == 0 ? "needs a number" : "neither an option nor a catalogue shader");
            return 2;
        }
    }
    std::vector<std::uint8_t> texels;
    for (int t = 0; t < 64 * 64 * 4; ++t) texels.push_back(std::uint8_t(t % 13 * 19));
    const glsl::sampler2D texture(64, 64, texels.data(), {});
    const glsl::sampler3D volume(16, 16, 16, texels.data(), {glsl::Wrap::Repeat, glsl::Wrap::Repeat, glsl::Wrap::Repeat});
    Uniforms u;
    u.time = 0.5f;
    u.teximage = &texture;
    const FragmentBatch a = batch_at(0.0f);
    const FragmentBatch b = batch_at(4.0f);
    ColorBatch out_a, out_b;

    std::printf("| shader | mode | wide_batches | two shade() ns | one shade_pair() ns | pair / two |\n");
    std::printf("|---|---|---|---|---|---|\n");
    for (const Program* program : catalogue()) {
        const ShaderInfo& info = program->info();
        if (!only.empty() && std::find(only.begin(), only.end(), std::string(info.name)) == only.end()) continue;
        // Each declared sampler bound to a texture of its kind, as a scene binds them.
        for (std::size_t i = 0; i < info.needs.samplers.size(); ++i) {
            const SamplerUse& use = info.needs.samplers[i];
            u.samplers[i] = use.name.empty() ? nullptr : use.dims == 3 ? static_cast<const glsl::Texture*>(&volume) : &texture;
        }
        const DrawShading shading = choose_shading(info.needs, false, ShadeRequest{});
        const ShadeMode mode = shading.mode;
        // Independent calls, as the rasterizer's blocks are: the CPU may overlap them.
        const double two = time_ns(repeat, [&] {
            program->shade(mode, a, u, out_a);
            program->shade(mode, b, u, out_b);
        });
        const double pair = time_ns(repeat, [&] { program->shade_pair(mode, a, b, u, out_a, out_b); });
        sink = out_a.rgba[0][0] + out_b.rgba[0][0];
        std::printf("| %s | %s | %s | %.1f | %.1f | %.2f |\n", std::string(info.name).c_str(),
                    shading.quads ? "fine quads" : "pixels", info.wide_batches ? "yes" : "no", two, pair,
                    pair / two);
    }
    return 0;
}
