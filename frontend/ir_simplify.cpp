#include "frontend/ir_simplify.h"

#include <cstdint>
#include <limits>

#include "frontend/ir_operands.h"

namespace qs::frontend {

void remove_instructions(ir::Stage& stage, const std::vector<bool>& removed) {
    std::vector<ir::Instr>& code = stage.code;
    std::vector<std::uint32_t> index(code.size() + 1);
    std::vector<ir::Instr> kept;
    kept.reserve(code.size());
    for (std::size_t i = 0; i < code.size(); ++i) {
        index[i] = std::uint32_t(kept.size());
        if (!removed[i]) kept.push_back(code[i]);
    }
    index[code.size()] = std::uint32_t(kept.size());
    for (ir::Instr& in : kept) {
        if (ir::jumps(in.op)) in.target = index[in.target];
    }
    code = std::move(kept);
}

void drop_idle_calls(ir::Stage& stage) {
    const std::vector<ir::Instr>& code = stage.code;
    std::vector<bool> removed(code.size(), false);
    // A Return whose next instruction ends its function (a CallEnd closes the innermost open
    // construct, which is then the Return's own call) or the stage: no instruction runs under
    // the mask it sets before the mask is restored.
    ir::Op next = ir::Op::CallEnd;  // the stage's end counts as one
    for (std::size_t i = code.size(); i-- > 0;) {
        if (code[i].op == ir::Op::Return && next == ir::Op::CallEnd) {
            removed[i] = true;
            continue;
        }
        next = code[i].op;
    }
    // A call whose own lanes never return: its end restores the mask its beginning saved.
    struct Open {
        std::size_t begin;
        bool returns;
    };
    std::vector<Open> calls;
    for (std::size_t i = 0; i < code.size(); ++i) {
        if (removed[i]) continue;
        if (code[i].op == ir::Op::CallBegin) calls.push_back({i, false});
        if (code[i].op == ir::Op::Return && !calls.empty()) calls.back().returns = true;
        if (code[i].op == ir::Op::CallEnd && !calls.empty()) {
            if (!calls.back().returns) removed[calls.back().begin] = removed[i] = true;
            calls.pop_back();
        }
    }
    remove_instructions(stage, removed);
}

void join_component_runs(ir::Stage& stage) {
    const std::vector<ir::Instr>& code = stage.code;
    std::vector<bool> target(code.size() + 1, false), removed(code.size(), false);
    for (const ir::Instr& in : code) {
        if (ir::jumps(in.op)) target[in.target] = true;
    }
    std::vector<ir::Instr> joined = code;
    for (std::size_t first = 0; first < code.size();) {
        const ir::Instr& head = code[first];
        std::size_t end = first + 1;
        if (ir::component_wise(head.op) && head.n == 1) {
            // Each of a, b, c steps by one register (bit set in `steps`) or stays on one (in
            // `stays`), the same way along the run; a field the operation does not read stays.
            std::uint8_t steps = 0, stays = 0;
            const auto follows = [&](const ir::Instr& prev, const ir::Instr& in) {
                const std::uint32_t from[3] = {prev.a, prev.b, prev.c}, to[3] = {in.a, in.b, in.c};
                std::uint8_t s = steps, t = stays;
                for (int k = 0; k < 3; ++k) {
                    const std::uint8_t bit = std::uint8_t(1u << k);
                    if (to[k] == from[k] + 1 && !(t & bit))
                        s |= bit;
                    else if (to[k] == from[k] && !(s & bit))
                        t |= bit;
                    else
                        return false;
                }
                steps = s, stays = t;
                return true;
            };
            constexpr std::size_t kLongest = std::numeric_limits<decltype(head.n)>::max();
            while (end < code.size() && end - first < kLongest) {
                const ir::Instr& in = code[end];
                const bool same = in.op == head.op && in.bank == head.bank && in.masked == head.masked && in.n == 1;
                if (target[end] || !same || in.d != code[end - 1].d + 1 || !follows(code[end - 1], in)) break;
                removed[end++] = true;
            }
            joined[first].n = std::uint8_t(end - first);
            joined[first].broadcast = end - first > 1 ? stays : 0;
        }
        first = end;
    }
    stage.code = std::move(joined);
    remove_instructions(stage, removed);
}

}  // namespace qs::frontend
