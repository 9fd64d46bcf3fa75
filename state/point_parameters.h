// GL 1.4 point parameters (ARB/EXT_point_parameters): glPointParameter*, their glGet and the
// per-draw snapshot. The values live in Context::draw_state.point_params.
#pragma once
#include "raster/vertex_transform.h"
#include "state/get_values.h"

namespace pineda {

bool query_point_parameters(Context& ctx, unsigned pname, GetValues& out);
// Asks the vertex stage for a size per vertex when the size is attenuated.
void snapshot_point_parameters(const Context& ctx, raster::Transform& t);

}  // namespace pineda
