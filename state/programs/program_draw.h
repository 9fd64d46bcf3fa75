// Draws while a program is in use (GL 2.0 2.15): the vertex shader over batches of 16
// vertices, then clipping, setup and binning with the shader's varyings, and the fragment
// shader in the tiles.
#pragma once
#include <cstdint>
#include <span>

#include "raster/draw_state.h"
#include "raster/vertex.h"
#include "state/programs/generic_attribs.h"

namespace pineda {

class Context;

// False when the program in use replaces no stage (a program linked without shaders): the
// fixed-function path draws.
bool draw_with_program(Context& ctx, raster::Primitive primitive, std::span<const raster::VertexInput> vertices,
                       std::span<const uint32_t> indices, AttribSource source);

}  // namespace pineda
