// Full unrolling of loops whose trip count is known at link time (GLSL ES 1.00 Appendix A
// loops and most desktop ones: `for (int i = 0; i < 6; ++i)`), so that their bodies become
// straight-line code that the other passes simplify across iterations.
#pragma once
#include "shader/ir.h"

namespace pineda::shader {

// Replaces each loop whose test and increment compute only from constants and from
// registers set to constants just before the loop (in the loop's own region), whose body
// writes none of those registers and has no break or continue of its own, by one copy of
// test, body and increment per iteration and a last test, while the program stays within a
// size limit. Returns whether a loop was unrolled (jump targets are then stale: fix_jumps).
bool unroll_constant_loops(ir::Code& code);

}  // namespace pineda::shader
