#pragma once
// A user's GLSL shader pair as a Program (shading/program.h), run by the interpreter: the
// renderer draws it like any catalogue shader, under every derivative rule, in double, with
// Dual2's analytic derivatives and with the undefined-case mask. Built from the front end's
// compiled program (frontend/compile.h).

#include <atomic>
#include <deque>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "frontend/compile.h"
#include "jit/compiled_blocks.h"
#include "shading/program.h"

namespace qs::interpreter {

class GlslProgram final : public Program {
public:
    // Whether float lanes run the fragment stage's straight runs of float arithmetic as machine
    // code (native_blocks.h), or every instruction is interpreted.
    enum class Blocks { Compiled, Interpreted };

    // `name` as listings and messages name the shader. Throws frontend::GlslUnsupported for a
    // program the renderer cannot bind: more samplers, varyings or uniforms than it passes.
    // Where LLVM cannot start, the interpreter runs the blocks, with a warning.
    GlslProgram(std::string name, frontend::CompiledProgram compiled, Blocks blocks = Blocks::Compiled);

    const ShaderInfo& info() const override { return info_; }
    void vertex(const VertexIn& in, const Uniforms& u, VertexOut& out) const override;
    void shade(ShadeMode mode, const FragmentBatch& in, const Uniforms& u, ColorBatch& out) const override;
    void shade_pair(ShadeMode mode, const FragmentBatch& a, const FragmentBatch& b, const Uniforms& u, ColorBatch& out_a,
                    ColorBatch& out_b) const override;

    // The documented departures from `check`'s bar of the translation this GLSL is the source of
    // (their texts outlive the program: they are the translation's).
    void adopt_check_bounds(std::span<const CheckBound> bounds) { info_.check_bounds = bounds; }

    const ir::Program& program() const { return compiled_.program; }
    const frontend::GlslSource& vertex_source() const { return compiled_.vertex; }
    // glslang's warnings, and LLVM's where it could not start.
    const std::vector<std::string>& warnings() const { return compiled_.warnings; }
    // Whether float lanes run compiled blocks (compiled when they first shade).
    bool runs_compiled_blocks() const { return blocks_ != nullptr && !blocks_->failed(); }
    // Whether LLVM failed to compile the blocks, which the interpreter then ran.
    bool compiled_blocks_failed() const { return blocks_ != nullptr && blocks_->failed(); }
    // Whether a loop of some fragment was left at llvmpipe's iteration limit (65,535).
    bool reached_loop_limit() const { return loop_limit_.load(std::memory_order_relaxed); }

private:
    void shade_batches(ShadeMode mode, const FragmentBatch* const* in, int count, const Uniforms& u, ColorBatch* const* out) const;

    frontend::CompiledProgram compiled_;
    std::deque<std::string> strings_;  // what info_'s string_views point into
    std::vector<UniformDecl> uniforms_;
    ShaderInfo info_;
    int teximage_ = -1;                           // the sampler slot bound to Uniforms::teximage
    std::array<int, kMaxSamplers> samplers_{};    // Needs::samplers[i]'s sampler slot
    mutable std::atomic<bool> loop_limit_{false};
    std::unique_ptr<jit::CompiledBlocks> blocks_;  // the fragment stage's, where it has any
};

}  // namespace qs::interpreter
