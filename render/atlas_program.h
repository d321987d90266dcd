#pragma once
// A program drawn into a texture atlas: the wrapped shader's own vertex stage runs unchanged, so
// its varyings (the object position, texcoords, anything it computes) are what a live render
// interpolates, and only gl_Position is replaced by the vertex's TEXCOORD_0:
//     gl_Position = vec4(gl_MultiTexCoord0.st * 2.0 - 1.0, 0.0, 1.0);
// the blog's bake (the ProcTexGen articles: "render the objects into the texture, using the UV coordinates as
// the position"). The viewport then puts texcoord s at window x = s W and t at window y = t H,
// window row y being texture row y as glTexImage2D counts rows from t = 0: a frame's bottom row
// is the atlas's first row (t = 0). The reference's GLSL does the same (reference/gl_renderer.h).

#include "shading/program.h"

namespace qs {

class AtlasProgram final : public Program {
public:
    explicit AtlasProgram(const Program& shader) : shader_(shader) {}
    const ShaderInfo& info() const override { return shader_.info(); }
    void vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) const override {
        shader_.vertex(in, u, out);
        // st * 2 is exact, so GL's possible fused multiply-add gives these bits too.
        out.clip = glm::vec4(in.texcoord.x * 2.0f - 1.0f, in.texcoord.y * 2.0f - 1.0f, 0.0f, 1.0f);
    }
    void shade(ShadeMode mode, const FragmentBatch& in, const Uniforms& u, ColorBatch& out) const override {
        shader_.shade(mode, in, u, out);
    }
    void shade_pair(ShadeMode mode, const FragmentBatch& a, const FragmentBatch& b, const Uniforms& u, ColorBatch& out_a,
                    ColorBatch& out_b) const override {
        shader_.shade_pair(mode, a, b, u, out_a, out_b);
    }

private:
    const Program& shader_;
};

}  // namespace qs
