// The draw snapshot of fog, clip planes, texgen and the colour sum: what the vertex stage
// (Transform::extras) and the rasterizer (DrawState) read of them.
#pragma once
#include "raster/vertex_transform.h"

namespace pineda {

class Context;

// Whether texgen on one of the first `texture_units` units reads the eye-space normal.
bool texgen_needs_normal(const Context& ctx, int texture_units);

// Fills t.extras and the matching fields of ctx.draw_state.
void snapshot_vertex_extras(Context& ctx, raster::Transform& t, int texture_units);

}  // namespace pineda
