#pragma once
// HeightFieldOf<Shader, HeightShader>: a shader's `Height` (shading/height_field.h) as a
// HeightField, instantiated over float and double lanes and Dual2 of them. Include only from the
// .cpp that registers it, beside the shaders' own instantiations (program_of.h).

#include <string_view>

#include "shading/catalogue.h"
#include "shading/glsl.h"
#include "shading/height_field.h"
#include "shading/number/number.h"

namespace qs {

template <class Shader, class HeightShader>
class HeightFieldOf final : public HeightField {
    using H = typename Shader::Height;
    static_assert(std::is_same_v<H, typename HeightShader::Height>, "the height shader draws the shader's own height");

public:
    std::string_view shader() const override { return Shader::info.name; }
    std::string_view height_shader() const override { return HeightShader::info.name; }
    double amplitude() const override { return double(H::amplitude); }

    void heights(Precision precision, const PointBatch& p, double (&h)[kBatchLanes]) const override {
        if (precision == Precision::Double) {
            run<double>(p, h);
        } else {
            run<float>(p, h);
        }
    }
    void gradients(Precision precision, const PointBatch& p, const PointBatch& t, const PointBatch& b,
                   double (&h)[kBatchLanes], double (&h_t)[kBatchLanes], double (&h_b)[kBatchLanes]) const override {
        if (precision == Precision::Double) {
            run_dual<double>(p, t, b, h, h_t, h_b);
        } else {
            run_dual<float>(p, t, b, h, h_t, h_b);
        }
    }

private:
    template <class T>
    using L = Pixels<T, kBatchLanes>;

    template <class T>
    static L<T> load(const double (&v)[kBatchLanes]) {
        alignas(64) T lanes[kBatchLanes];
        for (int i = 0; i < kBatchLanes; ++i) lanes[i] = T(v[i]);
        return L<T>::load(lanes);
    }
    template <class T>
    static void store(const L<T>& v, double (&out)[kBatchLanes]) {
        alignas(64) T lanes[kBatchLanes];
        v.store(lanes);
        for (int i = 0; i < kBatchLanes; ++i) out[i] = double(lanes[i]);
    }

    template <class T>
    static void run(const PointBatch& p, double (&h)[kBatchLanes]) {
        const glsl::vec3<L<T>> P(load<T>(p.x), load<T>(p.y), load<T>(p.z));
        store<T>(H::height(P), h);
    }
    // P(x, y) = p + x t + y b: value p, d/dx t, d/dy b. By the chain rule every operation of the
    // height carries d/dx and d/dy along (shading/number/dual2.h), so the result's partials are
    // dh/dx = grad h . dP/dx = grad h . t and dh/dy = grad h . b.
    template <class T>
    static void run_dual(const PointBatch& p, const PointBatch& t, const PointBatch& b, double (&h)[kBatchLanes],
                         double (&h_t)[kBatchLanes], double (&h_b)[kBatchLanes]) {
        using D = Dual2<L<T>>;
        const glsl::vec3<D> P(D(load<T>(p.x), load<T>(t.x), load<T>(b.x)), D(load<T>(p.y), load<T>(t.y), load<T>(b.y)),
                              D(load<T>(p.z), load<T>(t.z), load<T>(b.z)));
        const D r = H::height(P);
        store<T>(r.val, h);
        store<T>(r.dx, h_t);
        store<T>(r.dy, h_b);
    }
};

namespace registration {
template <class Shader, class HeightShader>
struct HeightRegistrar {
    HeightRegistrar() {
        static const HeightFieldOf<Shader, HeightShader> field;
        register_height_field(field);
    }
};
// One registration in the program however many files name it, as catalogue.h's.
template <class Shader, class HeightShader>
inline const HeightRegistrar<Shader, HeightShader> registered_height{};
}  // namespace registration

}  // namespace qs

// Registers Shader's height, drawn as grey by HeightShader (both catalogue shaders), at namespace
// scope after the line that registers the shaders.
#define QUADSHADE_HEIGHT_FIELD(Shader, HeightShader)                                                   \
    namespace {                                                                                        \
    [[maybe_unused]] const auto& QUADSHADE_REGISTRAR_NAME(__COUNTER__) =                               \
        ::qs::registration::registered_height<Shader, HeightShader>;                                   \
    }
