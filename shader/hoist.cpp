#include "shader/hoist.h"

#include <algorithm>

#include "shader/optimize.h"

namespace pineda::shader {
namespace {

using ir::Op;
using ir::Operand;

bool opens(Op op) { return op == Op::IfBegin || op == Op::LoopBegin || op == Op::FuncBegin; }
bool closes(Op op) { return op == Op::EndIf || op == Op::LoopEnd || op == Op::FuncEnd; }

// Calls f(register) for every register `in` writes.
template <class F>
void for_each_write(const ir::Code& code, const ir::Inst& in, F f) {
  if (in.op == Op::Texture) {
    for (Operand d : code.textures[static_cast<size_t>(in.i0)].dst)
      if (d != ir::kNone && !ir::is_const(d)) f(d);
  } else if (in.op == Op::Scatter) {
    for (int r = in.i0; r <= in.i0 + in.i1 && r < code.registers; ++r) f(r);
  } else if (in.d != ir::kNone && in.d >= 0) {
    f(in.d);
  }
}

}  // namespace

HoistedCode hoist_uniform_operations(const ir::Code& code) {
  const size_t n = code.insts.size();
  // Registers reached through a dynamic index keep every write.
  std::vector<char> dynamic(static_cast<size_t>(code.registers), 0);
  for (const ir::Inst& in : code.insts)
    if (in.op == Op::Gather || in.op == Op::Scatter)
      for (int r = in.i0; r <= in.i0 + in.i1 && r < code.registers; ++r) dynamic[static_cast<size_t>(r)] = 1;

  std::vector<char> blocked(n, 0);
  std::vector<char> hoisted(n, 0);
  std::vector<int> slot_of;             // register -> slot holding its current value, or -1
  std::vector<int> slot_source;         // slot -> instruction
  std::vector<std::vector<std::pair<int, int>>> reads;  // per instruction: (register, slot) read from a slot
  // Repeated until no hoisted value would be needed by a partial (masked) write: such
  // operations stay in the per-block code (after a few rounds, all of them do).
  constexpr int kRounds = 8;
  for (int round = 0;; ++round) {
    std::fill(hoisted.begin(), hoisted.end(), 0);
    slot_of.assign(static_cast<size_t>(code.registers), -1);
    slot_source.clear();
    reads.assign(n, {});
    std::vector<int> conflicts;
    int depth = 0;
    auto invalidate = [&](Operand r, bool partial) {
      int& s = slot_of[static_cast<size_t>(r)];
      if (s >= 0 && partial) conflicts.push_back(slot_source[static_cast<size_t>(s)]);
      s = -1;
    };
    auto note_read = [&](size_t i, Operand o) {
      if (o != ir::kNone && o >= 0 && o < code.registers && slot_of[static_cast<size_t>(o)] >= 0)
        reads[i].emplace_back(o, slot_of[static_cast<size_t>(o)]);
    };
    for (size_t i = 0; i < n; ++i) {
      const ir::Inst& in = code.insts[i];
      if (closes(in.op)) --depth;
      if (in.op == Op::LoopBegin)  // a value the body writes must survive its back edge
        for (size_t j = i + 1; j <= static_cast<size_t>(in.i0) && j < n; ++j)
          for_each_write(code, code.insts[j], [&](Operand r) { invalidate(r, true); });
      if (in.op == Op::Texture) {
        const ir::TextureLookup& t = code.textures[static_cast<size_t>(in.i0)];
        note_read(i, t.sampler);
        for (Operand c : t.coord) note_read(i, c);
        note_read(i, t.lod);
      } else {
        note_read(i, in.a);
        note_read(i, in.b);
        note_read(i, in.c);
      }
      bool uniform = depth == 0 && !blocked[i] && in.d >= 0 && !dynamic[static_cast<size_t>(in.d)] &&
                     (in.op == Op::LoadUniform || ir::op_is_pure_arith(in.op));
      if (uniform && in.op != Op::LoadUniform) {
        const Operand operands[3] = {in.a, in.b, in.c};
        for (int k = 0; k < ir::op_arity(in.op); ++k) {
          const Operand o = operands[k];
          uniform = uniform && (ir::is_const(o) || (o >= 0 && slot_of[static_cast<size_t>(o)] >= 0));
        }
      }
      if (uniform) {
        hoisted[i] = 1;
        slot_of[static_cast<size_t>(in.d)] = static_cast<int>(slot_source.size());
        slot_source.push_back(static_cast<int>(i));
      } else {
        for_each_write(code, in, [&](Operand r) { invalidate(r, depth > 0); });
      }
      if (opens(in.op)) ++depth;
    }
    if (conflicts.empty()) break;
    for (int c : conflicts) blocked[static_cast<size_t>(c)] = 1;
    if (round == kRounds) std::fill(blocked.begin(), blocked.end(), 1);
  }

  HoistedCode out;
  out.slots = static_cast<int>(slot_source.size());
  auto rewrite = [&](size_t i, Operand o) {
    for (const auto& [r, s] : reads[i])
      if (r == o) return code.registers + s;
    return o;
  };
  std::vector<int> slot_at(n, -1);
  for (size_t s = 0; s < slot_source.size(); ++s) slot_at[static_cast<size_t>(slot_source[s])] = static_cast<int>(s);
  out.textures = code.textures;
  for (size_t i = 0; i < n; ++i) {
    ir::Inst in = code.insts[i];
    if (in.op == Op::Texture) {
      ir::TextureLookup& t = out.textures[static_cast<size_t>(in.i0)];
      t.sampler = rewrite(i, t.sampler);
      for (Operand& c : t.coord) c = rewrite(i, c);
      t.lod = rewrite(i, t.lod);
    } else {
      in.a = rewrite(i, in.a);
      in.b = rewrite(i, in.b);
      in.c = rewrite(i, in.c);
    }
    if (hoisted[i]) {
      in.d = code.registers + slot_at[i];
      out.uniform_ops.push_back(in);
      continue;
    }
    out.insts.push_back(in);
  }
  ir::Code renumbered;
  renumbered.insts = std::move(out.insts);
  fix_jumps(renumbered);
  out.insts = std::move(renumbered.insts);
  return out;
}

}  // namespace pineda::shader
