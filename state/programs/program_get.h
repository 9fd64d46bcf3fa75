// glGet* and glEnable for the GL 2.0 programmable-pipeline state: the program in use, the
// limits, VERTEX_PROGRAM_POINT_SIZE and VERTEX_PROGRAM_TWO_SIDE.
#pragma once
#include "state/get_values.h"

namespace pineda {

bool query_program_state(Context& ctx, unsigned pname, GetValues& out);
bool* program_capability(Context& ctx, unsigned cap);

}  // namespace pineda
