// glGet* of fog, clip planes, stipple, texgen, secondary colour and their arrays.
#pragma once
#include "state/get_values.h"

namespace pineda {

bool query_vertex_extras(Context& ctx, unsigned pname, GetValues& out);

}  // namespace pineda
