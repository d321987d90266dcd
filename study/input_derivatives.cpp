#include "study/input_derivatives.h"

#include <stdexcept>

#include "shading/glsl.h"
#include "shading/program_of.h"

namespace qs::study {

namespace {

class InputDerivatives final : public Program {
public:
    InputDerivatives(const Program& inner, int varying, std::string name)
        : inner_(inner), varying_(varying), name_(std::move(name)), info_(inner.info()) {
        info_.name = name_;
        info_.needs.derivatives = true;
        info_.wide_batches = false;
    }

    const ShaderInfo& info() const override { return info_; }
    void vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) const override { inner_.vertex(in, u, out); }

    void shade(ShadeMode mode, const FragmentBatch& in, const Uniforms&, ColorBatch& out) const override {
        if (mode.precision == Precision::Double || mode.check_undefined) {
            throw std::logic_error("input derivative maps are shaded in float, unchecked");
        }
        switch (mode.derivatives) {
            case Derivatives::None:
            case Derivatives::Fine:
                return run<Quads<float, kBatchQuads, DerivativeRule::Fine>>(in, out);
            case Derivatives::CoarseLower:
                return run<Quads<float, kBatchQuads, DerivativeRule::CoarseLower>>(in, out);
            case Derivatives::CoarseUpper:
                return run<Quads<float, kBatchQuads, DerivativeRule::CoarseUpper>>(in, out);
            case Derivatives::Analytic:
                return run<Dual2<Pixels<float, kBatchLanes>>>(in, out);
        }
    }
    void shade_pair(ShadeMode mode, const FragmentBatch& a, const FragmentBatch& b, const Uniforms& u,
                    ColorBatch& out_a, ColorBatch& out_b) const override {
        shade(mode, a, u, out_a);
        shade(mode, b, u, out_b);
    }

private:
    template <class F>
    void run(const FragmentBatch& in, ColorBatch& out) const {
        using program_detail::load, program_detail::store;
        const F v = load<F>(in.varying[varying_], in.varying_dx[varying_], in.varying_dy[varying_]);
        store(glsl::dFdx(v), out.rgba[0]);
        store(glsl::dFdy(v), out.rgba[1]);
        store(v, out.rgba[2]);
        for (int i = 0; i < kBatchLanes; ++i) out.rgba[3][i] = 1.0f;
        out.discarded = 0;
    }

    const Program& inner_;
    int varying_;
    std::string name_;
    ShaderInfo info_;
};

}  // namespace

std::unique_ptr<Program> input_derivatives(const Program& inner, int varying, std::string name) {
    if (varying < 0 || varying >= inner.info().needs.varyings) {
        throw std::invalid_argument(std::string(inner.info().name) + " has no varying " + std::to_string(varying));
    }
    return std::make_unique<InputDerivatives>(inner, varying, std::move(name));
}

std::string varying_name(const ShaderInfo& info, int v) {
    switch (info.needs.coordinates) {
        case Coordinates::Texcoord2D:
            if (v < 2) return std::string("st.") + "st"[v];
            break;
        case Coordinates::Object2D:
        case Coordinates::Object3D:
            if (v < 3) return std::string("P.") + "xyz"[v];
            break;
        case Coordinates::None:
            break;
    }
    return "varying " + std::to_string(v);
}

}  // namespace qs::study
