// Local renaming: in straight-line code, every value a register holds before it is written
// again gets a register of its own, so that copy propagation, common subexpressions and
// dead-code elimination (which work on registers written once) see through variables that
// are assigned several times (`q = fract(q); q += dot(q, q)`).
#pragma once
#include "shader/ir.h"

namespace pineda::shader {

// Within each stretch of instructions without structure, a write of a register that the
// same stretch writes again later goes to a fresh register, and the reads in between read
// that one. The last write in a stretch keeps the register, so what flows out of the stretch
// is where it was. Registers reached through a dynamic index are left alone. Returns whether
// anything was renamed.
bool rename_local_values(ir::Code& code);

}  // namespace pineda::shader
