// Uniform-only operations taken out of a stage's per-block code: loads of uniforms, and
// arithmetic on them and on constants, outside every branch, loop and function frame. They run
// once per draw (Program::hoisted_fragment_values) or once per run; the code that stays reads
// their results from slots: registers numbered from code.registers up, never written there.
#pragma once
#include <vector>

#include "shader/ir.h"

namespace pineda::shader {

struct HoistedCode {
  std::vector<ir::Inst> insts;                // the per-block code; jump targets renumbered
  std::vector<ir::TextureLookup> textures;    // its lookups, slot operands rewritten the same way
  std::vector<ir::Inst> uniform_ops;          // in order; d and register operands are slots
  int slots = 0;                              // slot s is register code.registers + s
};

HoistedCode hoist_uniform_operations(const ir::Code& code);

}  // namespace pineda::shader
