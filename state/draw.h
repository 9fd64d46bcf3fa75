// The draw path's state side: snapshot what a draw needs, run the vertex stage, hand the
// primitives to the renderer.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <span>

#include "raster/vertex.h"

namespace pineda {

class Context;

// `mode` must already be a valid primitive enum.
void draw_vertices(Context& ctx, GLenum mode, std::span<const raster::VertexInput> vertices,
                   std::span<const uint32_t> indices);

}  // namespace pineda
