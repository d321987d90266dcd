#pragma once
// A batch's shader inputs from the triangle being rasterized: gl_FragCoord, the varyings and,
// for analytic derivatives, their screen derivatives, at sixteen pixels. Each lane computes
// exactly what PlaneEquation::at (or at_fused) and the reference's perspective division compute.
//
// Everything it reads is copied in, once per triangle, and a tile's loop keeps its own copy,
// which the shader calls between its blocks cannot reach: read through the renderer's members,
// every plane and choice would be loaded and tested again after each (opaque) call.

#include <array>
#include <cstddef>

#include "core/lanes16.h"
#include "core/prepared_draw.h"
#include "raster/plane_equation.h"
#include "raster/triangle_setup.h"
#include "shading/batches.h"
#include "shading/shade_mode.h"

namespace qs {

class FragmentInputs {
public:
    FragmentInputs() = default;
    // Triangle t of draw d in a framebuffer `height` pixels high; `depth_test`: the depth is
    // written, so gl_FragCoord.z is needed whatever the shader reads.
    FragmentInputs(const TriangleSetup& t, const PreparedDraw& d, bool depth_test, int height)
        : z_(t.z), inv_w_(t.inv_w), varyings_(t.varyings), count_(d.varyings), flat_(d.flat | d.noperspective),
          linear_(d.noperspective),
          frag_coord_(d.frag_coord), depth_(depth_test), analytic_(d.mode.derivatives == Derivatives::Analytic),
          // An affine triangle (equal w at its vertices, 1/w a constant plane) shares one
          // reciprocal, the same number each lane would compute.
          affine_(t.inv_w.dadx == 0.0f && t.inv_w.dady == 0.0f), affine_rcp_(1.0f / t.inv_w.a0),
          height_(float(height)) {}

    // Plane p at the lanes' pixels (x, y), each lane as PlaneEquation::at (or at_fused). Always
    // inlined, as the two below: where sixteen floats are not one register (AVX2), a call passes
    // them and its result through memory, in pieces a whole load cannot be forwarded from.
    template <bool Fused>
    [[gnu::always_inline]] static lanes16::Floats at(const PlaneEquation& p, const lanes16::Floats& x, const lanes16::Floats& y) {
        return at_row<Fused>(p.dady, at_column<Fused>(p, x), y);
    }
    // The same in two steps, as both forms add x's term first: x's term (a0 + dadx x, fused
    // fma(dadx, x, a0)), which a column of pixels shares, then y's.
    template <bool Fused>
    [[gnu::always_inline]] static lanes16::Floats at_column(const PlaneEquation& p, const lanes16::Floats& x) {
        using lanes16::broadcast;
        if constexpr (Fused) {
            return lanes16::fma(broadcast(p.dadx), x, broadcast(p.a0));
        } else {
            return p.a0 + p.dadx * x;
        }
    }
    template <bool Fused>
    [[gnu::always_inline]] static lanes16::Floats at_row(float dady, const lanes16::Floats& column, const lanes16::Floats& y) {
        if constexpr (Fused) {
            return lanes16::fma(lanes16::broadcast(dady), y, column);
        } else {
            return column + dady * y;
        }
    }
    // The same three on register-wide parts (lanes16::Wide), the same operations.
    template <bool Fused>
    [[gnu::always_inline]] static lanes16::Wide at(const PlaneEquation& p, const lanes16::Wide& x, const lanes16::Wide& y) {
        return at_row<Fused>(p.dady, at_column<Fused>(p, x), y);
    }
    template <bool Fused>
    [[gnu::always_inline]] static lanes16::Wide at_column(const PlaneEquation& p, const lanes16::Wide& x) {
        using Wide = lanes16::Wide;
        if constexpr (Fused) {
            return lanes16::fma(Wide::splat(p.dadx), x, Wide::splat(p.a0));
        } else {
            return Wide::splat(p.a0) + Wide::splat(p.dadx) * x;
        }
    }
    template <bool Fused>
    [[gnu::always_inline]] static lanes16::Wide at_row(float dady, const lanes16::Wide& column, const lanes16::Wide& y) {
        using Wide = lanes16::Wide;
        if constexpr (Fused) {
            return lanes16::fma(Wide::splat(dady), y, column);
        } else {
            return column + Wide::splat(dady) * y;
        }
    }

    // The window depth at the lanes' pixels.
    template <bool Fused>
    lanes16::Floats depth(const lanes16::Floats& x, const lanes16::Floats& y) const {
        return at<Fused>(z_, x, y);
    }

    // The inputs of the lanes at pixels (x, y) (framebuffer coordinates, y down) into `in`,
    // computed on register-wide parts (lanes16::Wide: where sixteen floats are two registers,
    // lanes16::Floats temporaries went through the stack piece by piece).
    template <bool Fused>
    [[gnu::always_inline]] void fill(FragmentBatch& in, const lanes16::Floats& x16, const lanes16::Floats& y16) const {
        using Wide = lanes16::Wide;
        const auto splat = [](float v) { return Wide::splat(v); };
        const Wide x = lanes16::to_wide(x16), y = lanes16::to_wide(y16);
        if (frag_coord_) {
            (x + splat(0.5f)).store(in.frag_coord[0]);
            (splat(height_) - (y + splat(0.5f))).store(in.frag_coord[1]);  // GL window y points up
            at<Fused>(z_, x, y).store(in.frag_coord[2]);
            at<Fused>(inv_w_, x, y).store(in.frag_coord[3]);
        } else if (depth_) {
            at<Fused>(z_, x, y).store(in.frag_coord[2]);  // the depth written
        }
        if (analytic_ && frag_coord_) {
            // Framebuffer y points down, GL's up: d/dy_GL = -d/dy_framebuffer.
            splat(z_.dadx).store(in.frag_coord_dx[0]);
            splat(-z_.dady).store(in.frag_coord_dy[0]);
            splat(inv_w_.dadx).store(in.frag_coord_dx[1]);
            splat(-inv_w_.dady).store(in.frag_coord_dy[1]);
        }
        if (count_ == 0) return;
        const Wide rcp = affine_ ? splat(affine_rcp_) : splat(1.0f) / at<Fused>(inv_w_, x, y);
        for (int v = 0; v < count_; ++v) {
            const PlaneEquation& p = varyings_[std::size_t(v)];
            const bool flat = flat_ >> v & 1;
            // flat_ holds the noperspective varyings too: neither is divided by the interpolated w.
            const Wide value = (linear_ >> v & 1) ? at<Fused>(p, x, y) : flat ? splat(p.a0) : at<Fused>(p, x, y) * rcp;
            value.store(in.varying[v]);
            if (analytic_) {
                // value = A / W with A, W linear: d(value)/dx = (dA/dx - value dW/dx) / W; a flat
                // varying enters as 0 (its plane is constant: zero derivatives); a noperspective
                // one's are its plane's.
                if (linear_ >> v & 1) {
                    splat(p.dadx).store(in.varying_dx[v]);
                    splat(-p.dady).store(in.varying_dy[v]);
                    continue;
                }
                const Wide v0 = flat ? splat(0.0f) : value;
                ((splat(p.dadx) - v0 * splat(inv_w_.dadx)) * rcp).store(in.varying_dx[v]);
                (-((splat(p.dady) - v0 * splat(inv_w_.dady)) * rcp)).store(in.varying_dy[v]);
            }
        }
    }

    // Whether a batch's inputs are only varyings, none flat, of an affine triangle: each the
    // plane's value times the one reciprocal (no gl_FragCoord, no depth, no analytic
    // derivatives). ColumnVaryings fills such inputs; `count` varyings of them.
    bool only_smooth_varyings() const { return !frag_coord_ && !depth_ && !analytic_ && affine_ && flat_ == 0; }
    int count() const { return count_; }

    // fill for the blocks of a tile whose inputs are only_smooth_varyings(), Count of them: each
    // varying's x term at the tile's Columns columns of blocks computed once, a block's inputs
    // are then one step a varying (y's term) and the reciprocal's product, with the varyings'
    // count known to the compiler. The same numbers as fill: each lane's at<Fused> times the
    // reciprocal, without fill's tests and loop over the varyings (docs/design.md, Rasterizer).
    template <bool Fused, int Count, int Columns>
    class ColumnVaryings {
    public:
        // `lanes_x(i)`: the lanes' x in column i.
        template <class LanesX>
        ColumnVaryings(const FragmentInputs& in, const LanesX& lanes_x) : rcp_(Wide::splat(in.affine_rcp_)) {
            for (int v = 0; v < Count; ++v) dady_[v] = Wide::splat(in.varyings_[std::size_t(v)].dady);
            for (int i = 0; i < Columns; ++i) {
                const lanes16::Floats x = lanes_x(i);
                for (int v = 0; v < Count; ++v) {
                    const lanes16::Floats column = at_column<Fused>(in.varyings_[std::size_t(v)], x);
                    column_[i][v] = lanes16::to_wide(column);
                }
            }
        }
        // The inputs of the block in column i whose lanes' y is y: at_row's value, in registers.
        [[gnu::always_inline]] void fill(FragmentBatch& batch, int i, const lanes16::Floats& y) const {
            const Wide wy = lanes16::to_wide(y);
            for (int v = 0; v < Count; ++v) {
                const Wide value = Fused ? lanes16::fma(dady_[v], wy, column_[i][v]) : column_[i][v] + dady_[v] * wy;
                (value * rcp_).store(batch.varying[v]);
            }
        }

    private:
        using Wide = lanes16::Wide;  // the block's values in registers (core/lanes16.h: why)
        Wide column_[Columns][Count];
        Wide rcp_;
        Wide dady_[Count];
    };

private:
    PlaneEquation z_, inv_w_;
    std::array<PlaneEquation, kMaxVaryings> varyings_{};
    int count_ = 0;       // varyings in use
    unsigned flat_ = 0;   // bit v: varying v is flat (the provoking vertex's value, in its a0) or noperspective
    unsigned linear_ = 0; // bit v: varying v is noperspective (its plane's value, not divided by w)
    bool frag_coord_ = false, depth_ = false, analytic_ = false, affine_ = false;
    float affine_rcp_ = 0.0f;  // 1/w of an affine triangle
    float height_ = 0.0f;
};

}  // namespace qs
