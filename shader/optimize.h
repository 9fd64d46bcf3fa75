// IR passes run at link time (all independent of uniform values): jump targets, constant
// folding, algebraic simplification, copy propagation, dead-code elimination, register
// compaction.
#pragma once
#include "shader/ir.h"

namespace pineda::shader {

// Sets the jump targets of the structure operations from their nesting.
void fix_jumps(ir::Code& code);

void optimize(ir::Code& code);

}  // namespace pineda::shader
