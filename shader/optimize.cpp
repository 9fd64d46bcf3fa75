#include "shader/optimize.h"

#include <algorithm>
#include <climits>
#include <functional>
#include <map>
#include <tuple>

#include "shader/early_textures.h"
#include "shader/ir_operands.h"
#include "shader/rename_values.h"
#include "shader/unroll_loops.h"

namespace pineda::shader {

using ir::Inst;
using ir::kNone;
using ir::Op;
using ir::Operand;
using ir::for_each_def;
using ir::for_each_use;
using ir::is_structure;

namespace {

struct RegInfo {
  int defs = 0;
  int def_pc = -1;
  std::vector<int> def_pcs;
  std::vector<int> use_pcs;
  bool pinned = false;  // read or written through a dynamic index
};

struct Analysis {
  std::vector<RegInfo> regs;
  std::vector<int> region;  // per instruction
  std::vector<int> parent;  // per region
  bool inside(int r, int ancestor) const {
    for (; r >= 0; r = parent[r])
      if (r == ancestor) return true;
    return false;
  }
  // A register written once whose every read follows the write inside its region: it holds
  // one value wherever it is read. Computed once per analysis (the passes ask per operand).
  std::vector<char> promotable_regs;
  bool promotable(int reg) const { return promotable_regs[static_cast<size_t>(reg)] != 0; }
  void find_promotable() {
    promotable_regs.assign(regs.size(), 0);
    for (size_t r = 0; r < regs.size(); ++r) {
      const RegInfo& info = regs[r];
      if (info.defs != 1 || info.pinned) continue;
      bool ok = true;
      for (int pc : info.use_pcs)
        if (pc <= info.def_pc || !inside(region[pc], region[info.def_pc])) {
          ok = false;
          break;
        }
      promotable_regs[r] = ok;
    }
  }
};

Analysis analyze(ir::Code& code) {
  Analysis an;
  an.regs.assign(code.registers, RegInfo{});
  an.region.resize(code.insts.size());
  an.parent.push_back(-1);
  std::vector<int> stack{0};
  auto push = [&] {
    an.parent.push_back(stack.back());
    stack.push_back(static_cast<int>(an.parent.size() - 1));
  };
  for (size_t pc = 0; pc < code.insts.size(); ++pc) {
    Inst& in = code.insts[pc];
    if (in.op == Op::Else || in.op == Op::EndIf || in.op == Op::LoopEnd || in.op == Op::FuncEnd ||
        in.op == Op::ContinuePoint)
      stack.pop_back();
    an.region[pc] = stack.back();
    if (in.op == Op::IfBegin || in.op == Op::Else || in.op == Op::LoopBegin || in.op == Op::FuncBegin ||
        in.op == Op::ContinuePoint)
      push();
    for_each_def(code, in, [&](Operand& d) {
      an.regs[d].defs++;
      an.regs[d].def_pc = static_cast<int>(pc);
      an.regs[d].def_pcs.push_back(static_cast<int>(pc));
    });
    for_each_use(code, in, [&](Operand& o) {
      if (o >= 0) an.regs[o].use_pcs.push_back(static_cast<int>(pc));
    });
    if (in.op == Op::Gather || in.op == Op::Scatter)
      for (int r = in.i0; r <= in.i0 + in.i1 && r < code.registers; ++r) {
        an.regs[r].pinned = true;
        an.regs[r].use_pcs.push_back(static_cast<int>(pc));
        if (in.op == Op::Scatter) an.regs[r].defs += 2;
      }
  }
  an.find_promotable();
  return an;
}

bool removable(Op op) {
  return ir::op_is_pure_arith(op) || op == Op::LoadUniform || op == Op::GatherUniform || op == Op::Gather ||
         op == Op::LoadInput || op == Op::LoadVarying || op == Op::LoadFragCoord || op == Op::LoadFrontFacing ||
         op == Op::LoadPointCoord || op == Op::Texture || op == Op::Ddx || op == Op::Ddy;
}

bool fold(ir::Code& code, Inst& in) {
  const int n = ir::op_arity(in.op);
  if (n == 0 || !ir::op_is_pure_arith(in.op)) return false;
  auto is_k = [&](Operand o, float v) { return ir::is_const(o) && code.const_value(o) == v; };
  auto to_mov = [&](Operand src) {
    in.op = Op::Mov;
    in.a = src;
    in.b = in.c = kNone;
    in.i1 = 0;
    return true;
  };
  if (in.op == Op::Mov) return false;
  bool all_const = ir::is_const(in.a) && (n < 2 || ir::is_const(in.b)) && (n < 3 || ir::is_const(in.c));
  if (all_const) {
    float v;
    if (n == 1) v = ir::eval_unary(in.op, code.const_value(in.a));
    else if (n == 2) v = ir::eval_binary(in.op, code.const_value(in.a), code.const_value(in.b));
    else v = ir::eval_ternary(in.op, code.const_value(in.a), code.const_value(in.b), code.const_value(in.c));
    return to_mov(code.constant(v));
  }
  switch (in.op) {
    case Op::Add:
      if (is_k(in.a, 0.0f)) return to_mov(in.b);
      if (is_k(in.b, 0.0f)) return to_mov(in.a);
      break;
    case Op::Sub:
      if (is_k(in.b, 0.0f)) return to_mov(in.a);
      break;
    // GL 2.1 2.1.1 asks 0 * x = x * 0 = 0 only for finite x (GLSL need not keep infinities
    // and NaNs; Mesa folds these too): a term weighted by zero, such as a convolution
    // kernel's texture lookup (glmark2 effect2d), then goes away with its operands.
    case Op::Mul:
      if (is_k(in.a, 1.0f)) return to_mov(in.b);
      if (is_k(in.b, 1.0f)) return to_mov(in.a);
      if (is_k(in.a, 0.0f) || is_k(in.b, 0.0f)) return to_mov(code.constant(0.0f));
      break;
    case Op::Div:
      if (is_k(in.b, 1.0f)) return to_mov(in.a);
      break;
    case Op::Select:
      if (ir::is_const(in.a)) return to_mov(code.const_value(in.a) != 0.0f ? in.b : in.c);
      if (in.b == in.c) return to_mov(in.b);
      break;
    case Op::Mad:
      if (is_k(in.a, 0.0f) || is_k(in.b, 0.0f)) return to_mov(in.c);
      if (is_k(in.c, 0.0f)) {
        in.op = Op::Mul;
        in.c = kNone;
        return true;
      }
      if (is_k(in.a, 1.0f) || is_k(in.b, 1.0f)) {
        Operand other = is_k(in.a, 1.0f) ? in.b : in.a;
        in.op = Op::Add;
        in.a = other;
        in.b = in.c;
        in.c = kNone;
        return true;
      }
      break;
    default:
      break;
  }
  return false;
}

// Removes the instructions marked dead.
void erase_dead(ir::Code& code, const std::vector<bool>& dead) {
  std::vector<Inst> kept;
  for (size_t pc = 0; pc < code.insts.size(); ++pc)
    if (!dead[pc]) kept.push_back(code.insts[pc]);
  code.insts.swap(kept);
}

bool pass(ir::Code& code) {
  bool changed = false;
  for (Inst& in : code.insts) changed |= fold(code, in);

  Analysis an = analyze(code);
  std::vector<bool> dead(code.insts.size(), false);
  // Common subexpressions: an operation on values that never change, computed again where an
  // earlier identical one is still in effect (same or enclosing region, earlier), becomes a
  // copy of the earlier result.
  {
    std::map<std::tuple<int, Operand, Operand, Operand, int, int>, std::vector<int>> seen;
    auto stable = [&](Operand o) { return o == kNone || ir::is_const(o) || (o >= 0 && an.promotable(o)); };
    for (size_t pc = 0; pc < code.insts.size(); ++pc) {
      Inst& in = code.insts[pc];
      const bool candidate = (ir::op_is_pure_arith(in.op) && in.op != Op::Mov) || in.op == Op::LoadUniform ||
                             in.op == Op::LoadVarying || in.op == Op::LoadInput || in.op == Op::LoadFragCoord ||
                             in.op == Op::LoadPointCoord || in.op == Op::LoadFrontFacing;
      if (!candidate || in.d < 0 || !an.promotable(in.d) || !stable(in.a) || !stable(in.b) || !stable(in.c)) continue;
      // fract(x) after floor(x) is x - floor(x), the value Fract computes.
      if (in.op == Op::Fract) {
        const auto floor_key = std::make_tuple(static_cast<int>(Op::Floor), in.a, kNone, kNone, 0, 0);
        const auto floors = seen.find(floor_key);
        int floor_pc = -1;
        if (floors != seen.end())
          for (int e : floors->second)
            if (an.inside(an.region[pc], an.region[e])) floor_pc = e;
        if (floor_pc >= 0) {
          in.op = Op::Sub;
          in.b = code.insts[floor_pc].d;
          changed = true;
          continue;
        }
      }
      auto key = std::make_tuple(static_cast<int>(in.op), in.a, in.b, in.c, in.i0, in.i1);
      std::vector<int>& earlier = seen[key];
      int found = -1;
      for (int e : earlier)
        if (an.inside(an.region[pc], an.region[e])) found = e;
      if (found >= 0) {
        in.op = Op::Mov;
        in.a = code.insts[found].d;
        in.b = in.c = kNone;
        in.i0 = in.i1 = 0;
        changed = true;
      } else {
        earlier.push_back(static_cast<int>(pc));
      }
    }
    if (changed) an = analyze(code);
  }
  // Copy propagation: a register that holds one value everywhere it is read takes the place
  // of its copies (chains resolve to the first source; one sweep, no re-analysis: a source
  // stays valid at every use of its copy).
  std::vector<Operand> replace(code.registers, kNone);
  bool propagated = false;
  auto resolve = [&](Operand o) {
    while (o >= 0 && replace[o] != kNone) o = replace[o];
    return o;
  };
  for (size_t pc = 0; pc < code.insts.size(); ++pc) {
    Inst& in = code.insts[pc];
    if (in.op != Op::Mov || in.d == kNone) continue;
    if (!an.promotable(in.d)) continue;
    if (!(ir::is_const(in.a) || (in.a >= 0 && an.promotable(in.a)))) continue;
    if (an.regs[in.d].use_pcs.empty()) continue;
    replace[in.d] = resolve(in.a);
    dead[pc] = true;
    propagated = true;
  }
  changed |= propagated;
  if (propagated) {
    for (Inst& in : code.insts)
      for_each_use(code, in, [&](Operand& o) { o = resolve(o); });
    an = analyze(code);
  }
  // A variable's zero initialisation is dropped when its one real assignment follows in the
  // same region with no read in between.
  for (size_t pc = 0; pc < code.insts.size(); ++pc) {
    Inst& in = code.insts[pc];
    if (dead[pc] || in.op != Op::Mov || in.i1 != 1 || in.d == kNone) continue;
    const RegInfo& info = an.regs[in.d];
    if (info.defs != 2 || info.pinned) continue;
    int other = -1;
    for (int q : info.def_pcs)
      if (q != static_cast<int>(pc)) other = q;
    if (other < static_cast<int>(pc) || dead[other] || an.region[other] != an.region[pc]) continue;
    bool read_between = false;
    for (int u : info.use_pcs) read_between = read_between || u <= other;
    if (read_between) continue;
    dead[pc] = true;
    changed = true;
  }
  // Dead code.
  for (size_t pc = 0; pc < code.insts.size(); ++pc) {
    Inst& in = code.insts[pc];
    if (dead[pc] || !removable(in.op)) continue;
    bool used = false;
    for_each_def(code, in, [&](Operand& d) { used = used || !an.regs[d].use_pcs.empty() || an.regs[d].pinned; });
    if (!used) {
      dead[pc] = true;
      changed = true;
    }
  }
  // t = op ...; v = mov t  becomes  v = op ...
  for (size_t pc = 1; pc < code.insts.size(); ++pc) {
    Inst& mov = code.insts[pc];
    Inst& def = code.insts[pc - 1];
    if (dead[pc] || dead[pc - 1] || mov.op != Op::Mov || mov.i1 == 1 || mov.a < 0 || def.d != mov.a) continue;
    if (def.op == Op::Texture || is_structure(def.op) || def.op == Op::Scatter) continue;
    const RegInfo& t = an.regs[mov.a];
    if (t.defs != 1 || t.pinned || t.use_pcs.size() != 1 || an.region[pc] != an.region[pc - 1]) continue;
    if (an.regs[mov.d].pinned) continue;
    def.d = mov.d;
    dead[pc] = true;
    changed = true;
  }
  if (changed) erase_dead(code, dead);
  return changed;
}

// t = mul a b; ...; d = add t c (or add c t), t read only there: d = mad a b c. Mad is
// a * b + c with two roundings (no FMA), so the values do not change; one dispatch instead of
// two. Not when a and b are both uniform-only: the mul is then computed once per draw
// (shader/hoist.h) and only the add runs per block.
bool fuse_multiply_add(ir::Code& code) {
  Analysis an = analyze(code);
  std::vector<char> uniform(code.registers, 0);
  auto uniform_only = [&](Operand o) { return o == kNone || ir::is_const(o) || (o >= 0 && uniform[o]); };
  for (size_t pc = 0; pc < code.insts.size(); ++pc) {
    const Inst& in = code.insts[pc];
    if (in.d < 0 || !an.promotable(in.d)) continue;
    if (in.op == Op::LoadUniform ||
        (ir::op_is_pure_arith(in.op) && uniform_only(in.a) && uniform_only(in.b) && uniform_only(in.c)))
      uniform[in.d] = 1;
  }
  auto stable = [&](Operand o) { return ir::is_const(o) || (o >= 0 && an.promotable(o)); };
  std::vector<bool> dead(code.insts.size(), false);
  bool changed = false;
  for (size_t pc = 0; pc < code.insts.size(); ++pc) {
    Inst& add = code.insts[pc];
    if (add.op != Op::Add) continue;
    for (Operand* t : {&add.a, &add.b}) {
      if (*t < 0 || !an.promotable(*t)) continue;
      const RegInfo& info = an.regs[*t];
      if (info.use_pcs.size() != 1 || an.region[info.def_pc] != an.region[pc]) continue;
      Inst& mul = code.insts[info.def_pc];
      if (mul.op != Op::Mul || dead[info.def_pc] || !stable(mul.a) || !stable(mul.b)) continue;
      if (uniform_only(mul.a) && uniform_only(mul.b)) continue;
      const Operand c = t == &add.a ? add.b : add.a;
      add = Inst{Op::Mad, add.d, mul.a, mul.b, c};
      dead[info.def_pc] = true;
      changed = true;
      break;
    }
  }
  if (changed) erase_dead(code, dead);
  return changed;
}

// Linear-scan register allocation over live intervals in instruction order. A value that
// crosses a loop's back edge (defined before the loop and read in it, or a variable assigned
// in several places) lives through the whole loop. Registers read or written through a
// dynamic index keep their order, first in the file, and are never shared.
void allocate_registers(ir::Code& code) {
  Analysis an = analyze(code);
  const int n = code.registers;
  std::vector<std::pair<int, int>> loops;
  {
    std::vector<int> open;
    for (size_t pc = 0; pc < code.insts.size(); ++pc) {
      if (code.insts[pc].op == Op::LoopBegin) open.push_back(static_cast<int>(pc));
      if (code.insts[pc].op == Op::LoopEnd) {
        loops.emplace_back(open.back(), static_cast<int>(pc));
        open.pop_back();
      }
    }
  }
  std::vector<int> first(n, INT_MAX), last(n, -1);
  for (int r = 0; r < n; ++r) {
    const RegInfo& info = an.regs[r];
    for (int pc : info.def_pcs) first[r] = std::min(first[r], pc), last[r] = std::max(last[r], pc);
    for (int pc : info.use_pcs) first[r] = std::min(first[r], pc), last[r] = std::max(last[r], pc);
    if (last[r] < 0 || info.pinned) continue;
    const bool single_value = an.promotable(r);
    for (const auto& [b, e] : loops) {
      bool inside = false;
      for (int pc : info.use_pcs) inside = inside || (pc > b && pc < e);
      for (int pc : info.def_pcs) inside = inside || (pc > b && pc < e);
      if (!inside) continue;
      if (!single_value) {
        first[r] = std::min(first[r], b);
        last[r] = std::max(last[r], e);
      } else if (first[r] < b) {
        last[r] = std::max(last[r], e);
      }
    }
  }
  std::vector<int> remap(n, -1);
  int next = 0;
  for (int r = 0; r < n; ++r)
    if (an.regs[r].pinned) remap[r] = next++;
  std::vector<int> order;
  for (int r = 0; r < n; ++r)
    if (!an.regs[r].pinned && last[r] >= 0) order.push_back(r);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return first[a] < first[b]; });
  std::vector<std::pair<int, int>> active;  // (last pc, physical register), a min-heap on last
  std::vector<int> free_regs;
  auto later = [](const std::pair<int, int>& a, const std::pair<int, int>& b) { return a.first > b.first; };
  for (int r : order) {
    while (!active.empty() && active.front().first < first[r]) {
      free_regs.push_back(active.front().second);
      std::pop_heap(active.begin(), active.end(), later);
      active.pop_back();
    }
    int phys;
    if (!free_regs.empty()) {
      phys = free_regs.back();
      free_regs.pop_back();
    } else {
      phys = next++;
    }
    remap[r] = phys;
    active.emplace_back(last[r], phys);
    std::push_heap(active.begin(), active.end(), later);
  }
  for (Inst& in : code.insts) {
    auto fix = [&](Operand& o) {
      if (o >= 0) o = remap[o];
    };
    for_each_def(code, in, fix);
    for_each_use(code, in, fix);
    if (in.op == Op::Gather || in.op == Op::Scatter) in.i0 = remap[in.i0];
  }
  code.registers = next;
}

}  // namespace

void fix_jumps(ir::Code& code) {
  std::vector<int> stack;
  for (size_t pc = 0; pc < code.insts.size(); ++pc) {
    Inst& in = code.insts[pc];
    const int here = static_cast<int>(pc);
    switch (in.op) {
      case Op::IfBegin: case Op::LoopBegin: case Op::FuncBegin:
        stack.push_back(here);
        break;
      case Op::Else:
        code.insts[stack.back()].i0 = here;
        stack.back() = here;
        break;
      case Op::EndIf:
        code.insts[stack.back()].i0 = here;
        stack.pop_back();
        break;
      case Op::LoopEnd:
        code.insts[stack.back()].i0 = here;
        in.i0 = stack.back() + 1;
        stack.pop_back();
        break;
      case Op::FuncEnd:
        stack.pop_back();
        break;
      default:
        break;
    }
  }
}

void optimize(ir::Code& code) {
  const ir::FlushDenormals flush;
  for (int round = 0; round < 32 && pass(code); ++round) {
  }
  // Unrolling first: it makes the longest stretches for renaming.
  const bool unrolled = unroll_constant_loops(code);
  if (rename_local_values(code) || unrolled)
    for (int round = 0; round < 32 && pass(code); ++round) {
    }
  if (fuse_multiply_add(code))
    for (int round = 0; round < 32 && pass(code); ++round) {
    }
  move_texture_lookups_early(code);
  allocate_registers(code);
  fix_jumps(code);
}

}  // namespace pineda::shader
