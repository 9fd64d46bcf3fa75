// The vertex that glVertex specifies: a position with the current attributes.
#pragma once
#include "raster/vertex.h"

namespace pineda {

class Context;

// `position` with the current colour, normal, texture coordinates, edge flag, secondary
// colour and fog coordinate (api_immediate.cpp).
raster::VertexInput current_vertex(const Context& ctx, float x, float y, float z, float w);

}  // namespace pineda
