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
// stretch reads (before anything writes that register again): one pass from the end, keeping the
// registers the lookups below read.
std::vector<char> feeds_lookups(ir::Code& code) {
  std::vector<char> feeds(code.insts.size());
  std::vector<Operand> read_below;
  for (size_t at = code.insts.size(); at-- > 0;) {
    Inst& in = code.insts[at];
    if (ir::is_structure(in.op)) {
      read_below.clear();
      continue;
    }
    feeds[at] = ir::op_is_pure_arith(in.op) && in.d >= 0 &&
                std::find(read_below.begin(), read_below.end(), in.d) != read_below.end();
    ir::for_each_def(code, in, [&](Operand& d) { std::erase(read_below, d); });
    if (in.op == Op::Texture) ir::for_each_use(code, in, [&](Operand& o) { if (o >= 0) read_below.push_back(o); });
  }
  return feeds;
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
  return moved;
}

}  // namespace pineda::shader
