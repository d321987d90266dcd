// Program::shade_pair gives exactly what shade() gives on each batch, for every catalogue shader
// in every mode: on AVX-512 the pair runs as one number of twice the width, so this checks that
// the wide instantiations and the batch-to-lane mapping of the pair change no bit.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "shading/catalogue.h"

namespace qs {
namespace {

// Inputs that vary per lane and per batch, inside the ranges the shaders see on screen, so that
// lanes differ (a lane mapped to the wrong half shows) and derivatives are non-zero.
FragmentBatch batch_at(float offset) {
    FragmentBatch in{};
    for (int i = 0; i < kBatchLanes; ++i) {
        const float x = offset + float(i % 4) + 0.37f * float(i / 4);
        const float y = 0.5f * offset + float(i / 4) - 0.21f * float(i % 4);
        in.frag_coord[0][i] = 0.5f + x, in.frag_coord[1][i] = 60.5f + y;
        in.frag_coord[2][i] = 0.25f + 0.01f * x, in.frag_coord[3][i] = 0.5f + 0.001f * y;
        for (int v = 0; v < kMaxVaryings; ++v) {
            in.varying[v][i] = std::sin(0.7f * x + 1.3f * float(v)) * (1.0f + float(v)) + 0.11f * y;
            in.varying_dx[v][i] = 0.01f * float(v + 1), in.varying_dy[v][i] = -0.02f * float(v + 1);
        }
        for (int k = 0; k < 2; ++k) in.frag_coord_dx[k][i] = 0.001f, in.frag_coord_dy[k][i] = -0.001f;
    }
    return in;
}

bool same_bits(const ColorBatch& a, const ColorBatch& b) { return std::memcmp(a.rgba, b.rgba, sizeof a.rgba) == 0; }

}  // namespace

TEST_CASE("shading two batches as a pair gives the bits of shading each alone, every shader and mode", "[program]") {
    std::vector<std::uint8_t> texels;
    for (int t = 0; t < 5 * 3 * 4; ++t) texels.push_back(std::uint8_t(t % 7 * 36));
    const glsl::sampler2D texture(5, 3, texels.data(), {});
    const glsl::sampler3D volume(5, 3, 1, texels.data(), {glsl::Wrap::Repeat, glsl::Wrap::Repeat, glsl::Wrap::Repeat});
    Uniforms u;
    u.time = 1.75f;
    u.teximage = &texture;
    const FragmentBatch a = batch_at(0.0f), b = batch_at(5.3f);
    int uniform = 0;  // shaders whose two batches came out the same: there a swap would not show
    for (const Program* program : catalogue()) {
        const bool derivatives = program->info().needs.derivatives;
        // Each named sampler gets a texture of the kind it declares.
        const auto& samplers = program->info().needs.samplers;
        for (std::size_t i = 0; i < samplers.size(); ++i) {
            u.samplers[i] = samplers[i].name.empty() ? nullptr
                            : samplers[i].dims == 3  ? static_cast<const glsl::Texture*>(&volume)
                                                     : &texture;
        }
        for (Derivatives d : {Derivatives::None, Derivatives::Fine, Derivatives::CoarseLower, Derivatives::CoarseUpper,
                              Derivatives::Analytic}) {
            if (d == Derivatives::None && derivatives) continue;
            for (Precision p : {Precision::Float, Precision::Double}) {
                ShadeMode mode;
                mode.derivatives = d, mode.precision = p;
                INFO(std::string(program->info().name) << ", derivatives " << int(d) << ", precision " << int(p));
                ColorBatch alone_a, alone_b, pair_a, pair_b;
                program->shade(mode, a, u, alone_a);
                program->shade(mode, b, u, alone_b);
                program->shade_pair(mode, a, b, u, pair_a, pair_b);
                CHECK(same_bits(alone_a, pair_a));
                CHECK(same_bits(alone_b, pair_b));
                if (d == Derivatives::Fine && p == Precision::Float && same_bits(alone_a, alone_b)) {
                    UNSCOPED_INFO("same colour in both batches: " << program->info().name);
                    ++uniform;
                }
            }
        }
    }
    CHECK(uniform == 1);  // the constant colour
}

}  // namespace qs
