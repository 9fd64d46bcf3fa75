#include "shader/early_textures.h"

#include <algorithm>
#include <vector>

#include "shader/ir_operands.h"

namespace pineda::shader {

using ir::Inst;
using ir::Op;
using ir::Operand;

namespace {

// Moves the instruction at `at` above those before it that it does not depend on and that do
// not depend on it, within its stretch, and not above one that `stays_above` marks (moved
// along with the instructions).
bool move_up(ir::Code& code, std::vector<char>& stays_above, size_t at) {
  std::vector<Operand> reads, writes;
  auto holds = [](const std::vector<Operand>& set, Operand o) { return std::find(set.begin(), set.end(), o) != set.end(); };
  ir::for_each_use(code, code.insts[at], [&](Operand& o) { if (o >= 0) reads.push_back(o); });
  ir::for_each_def(code, code.insts[at], [&](Operand& o) { if (o >= 0) writes.push_back(o); });
  size_t to = at;
  while (to > 0) {
    Inst& before = code.insts[to - 1];
    if (ir::is_structure(before.op) || before.op == Op::Gather || before.op == Op::Scatter || stays_above[to - 1]) break;
    bool depends = false;
    ir::for_each_def(code, before, [&](Operand& d) { depends = depends || holds(reads, d) || holds(writes, d); });
    ir::for_each_use(code, before, [&](Operand& o) { depends = depends || holds(writes, o); });
    if (depends) break;
    --to;
  }
  if (to == at) return false;
  const auto first = code.insts.begin() + static_cast<std::ptrdiff_t>(to);
  const auto moved = code.insts.begin() + static_cast<std::ptrdiff_t>(at);
  std::rotate(first, moved, moved + 1);
  std::rotate(stays_above.begin() + static_cast<std::ptrdiff_t>(to), stays_above.begin() + static_cast<std::ptrdiff_t>(at),
              stays_above.begin() + static_cast<std::ptrdiff_t>(at) + 1);
  return true;
}

// For each instruction, whether it is arithmetic whose result a later texture lookup of the same
// stretch reads, directly or through other such arithmetic (before anything writes that register
// again): one pass from the end, keeping the registers the lookups and their feeders below read.
// (A kernel's offsets computed from uniforms, `cos(a) * r`, feed its coordinates in two steps:
// with direct feeders only, each lookup stayed behind the last one's sums.)
std::vector<char> feeds_lookups(ir::Code& code) {
  std::vector<char> feeds(code.insts.size());
  // Per register, whether a lookup or a feeder below reads it (a set of flags: a long unrolled
  // stretch feeds many registers).
  const size_t registers = static_cast<size_t>(std::max(code.registers, 0));
  std::vector<char> read_below(registers);
  std::vector<size_t> flagged;  // the registers once flagged since the last structure
  auto flag = [&](Operand o) -> char* { return o >= 0 && static_cast<size_t>(o) < registers ? &read_below[static_cast<size_t>(o)] : nullptr; };
  for (size_t at = code.insts.size(); at-- > 0;) {
    Inst& in = code.insts[at];
    if (ir::is_structure(in.op)) {
      for (size_t r : flagged) read_below[r] = 0;
      flagged.clear();
      continue;
    }
    const char* d = flag(in.d);
    feeds[at] = ir::op_is_pure_arith(in.op) && d && *d;
    ir::for_each_def(code, in, [&](Operand& o) { if (char* f = flag(o)) *f = 0; });
    if (in.op == Op::Texture || feeds[at])
      ir::for_each_use(code, in, [&](Operand& o) {
        if (char* f = flag(o); f && !*f) {
          *f = 1;
          flagged.push_back(static_cast<size_t>(o));
        }
      });
  }
  return feeds;
}

// The operands the instruction at `at` reads and writes (registers only).
void registers_of(ir::Code& code, size_t at, std::vector<Operand>& reads, std::vector<Operand>& writes) {
  reads.clear();
  writes.clear();
  ir::for_each_use(code, code.insts[at], [&](Operand& o) { if (o >= 0) reads.push_back(o); });
  ir::for_each_def(code, code.insts[at], [&](Operand& o) { if (o >= 0) writes.push_back(o); });
}

// Moves each lookup down to just before the next lookup of its stretch when nothing between
// them depends on it or it on them, from the last lookup up, so that the lookups of a stretch
// end side by side (compiled code calls out once for such a run: jit::call_texture_run).
bool group_texture_lookups(ir::Code& code) {
  bool moved = false;
  std::vector<Operand> reads, writes, between_reads, between_writes;
  auto holds = [](const std::vector<Operand>& set, Operand o) { return std::find(set.begin(), set.end(), o) != set.end(); };
  for (size_t at = code.insts.size(); at-- > 0;) {
    if (code.insts[at].op != Op::Texture) continue;
    size_t next = at + 1;
    while (next < code.insts.size() && code.insts[next].op != Op::Texture && !ir::is_structure(code.insts[next].op) &&
           code.insts[next].op != Op::Gather && code.insts[next].op != Op::Scatter)
      ++next;
    if (next == code.insts.size() || code.insts[next].op != Op::Texture || next == at + 1) continue;
    registers_of(code, at, reads, writes);
    bool independent = true;
    for (size_t k = at + 1; k < next && independent; ++k) {
      registers_of(code, k, between_reads, between_writes);
      for (Operand o : between_reads) independent = independent && !holds(writes, o);
      for (Operand o : between_writes) independent = independent && !holds(reads, o) && !holds(writes, o);
    }
    if (!independent) continue;
    const auto first = code.insts.begin() + static_cast<std::ptrdiff_t>(at);
    std::rotate(first, first + 1, code.insts.begin() + static_cast<std::ptrdiff_t>(next));
    moved = true;
  }
  return moved;
}

}  // namespace

bool move_texture_lookups_early(ir::Code& code) {
  bool moved = false;
  // First the arithmetic that computes lookups' operands (coordinate offsets), so that the
  // lookups after it can rise as far; each keeps its order with the others.
  const size_t n = code.insts.size();
  std::vector<char> feeds = feeds_lookups(code);
  for (size_t at = 0; at < n; ++at)
    if (feeds[at]) moved |= move_up(code, feeds, at);
  std::vector<char> lookups(n);
  for (size_t at = 0; at < n; ++at) lookups[at] = code.insts[at].op == Op::Texture;
  for (size_t at = 0; at < n; ++at)
    if (lookups[at]) moved |= move_up(code, lookups, at);
  moved |= group_texture_lookups(code);
  return moved;
}

}  // namespace pineda::shader
