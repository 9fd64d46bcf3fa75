#include "shader/rename_values.h"

#include <vector>

#include "shader/ir_operands.h"

namespace pineda::shader {

using ir::Inst;
using ir::Operand;

bool rename_local_values(ir::Code& code) {
  const int original = code.registers;
  std::vector<char> pinned(static_cast<size_t>(original), 0);
  for (const Inst& in : code.insts)
    if (in.op == ir::Op::Gather || in.op == ir::Op::Scatter)
      for (int r = in.i0; r <= in.i0 + in.i1 && r < original; ++r) pinned[static_cast<size_t>(r)] = 1;
  auto renamable = [&](Operand r) { return r >= 0 && r < original && !pinned[static_cast<size_t>(r)]; };

  std::vector<int> writes_left(static_cast<size_t>(original), 0);
  std::vector<Operand> current(static_cast<size_t>(original));  // the register holding r's value
  for (int r = 0; r < original; ++r) current[static_cast<size_t>(r)] = r;
  bool renamed = false;
  const size_t n = code.insts.size();
  for (size_t start = 0; start < n;) {
    if (ir::is_structure(code.insts[start].op)) {
      ++start;
      continue;
    }
    size_t end = start;
    while (end < n && !ir::is_structure(code.insts[end].op)) ++end;
    for (size_t pc = start; pc < end; ++pc)
      ir::for_each_def(code, code.insts[pc], [&](Operand& d) {
        if (renamable(d)) ++writes_left[static_cast<size_t>(d)];
      });
    for (size_t pc = start; pc < end; ++pc) {
      Inst& in = code.insts[pc];
      ir::for_each_use(code, in, [&](Operand& o) {
        if (renamable(o)) o = current[static_cast<size_t>(o)];
      });
      ir::for_each_def(code, in, [&](Operand& d) {
        if (!renamable(d)) return;
        const size_t r = static_cast<size_t>(d);
        if (--writes_left[r] > 0) {
          current[r] = code.new_register();
          d = current[r];
          renamed = true;
        } else {
          current[r] = d;
        }
      });
    }
    start = end;
  }
  return renamed;
}

}  // namespace pineda::shader
