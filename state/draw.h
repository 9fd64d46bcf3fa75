// The draw path's state side: snapshot what a draw needs, run the vertex stage, hand the
// primitives to the renderer.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <span>

#include "raster/vertex.h"
#include "state/context.h"
#include "state/programs/generic_attribs.h"

namespace pineda {

class Context;

// `mode` must already be a valid primitive enum.
// `materials`, when not empty, gives the materials of runs of vertices (glMaterial inside
// glBegin/glEnd); its first entry starts at vertex 0.
void draw_vertices(Context& ctx, GLenum mode, std::span<const raster::VertexInput> vertices,
                   std::span<const uint32_t> indices,
                   std::span<const Context::MaterialChange> materials = {},
                   AttribSource generic_source = AttribSource::Current);

// One vertex through the vertex stage (transform, lighting, every unit's texture matrix):
// the raster position's vertex.
raster::ClipVertex transform_single_vertex(Context& ctx, const raster::VertexInput& vertex);

// The draw snapshot for fragments that do not come from primitives (pixel rectangles,
// bitmaps): the current fragment state with the bound textures.
const raster::DrawState& fragment_snapshot(Context& ctx);

}  // namespace pineda
