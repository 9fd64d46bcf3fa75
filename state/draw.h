// The draw path's state side: snapshot what a draw needs, run the vertex stage, hand the
// primitives to the renderer.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <functional>
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

// A draw's vertices in the vertex arrays: fetch(begin, end, out) reads vertices [begin, end)
// into out[0, end - begin); it may run on several threads at once.
struct ArrayVertices {
  size_t count = 0;
  std::function<void(size_t begin, size_t end, raster::VertexInput* out)> fetch;
  // The array element of each vertex of [begin, end) into out[0, end - begin).
  std::function<void(size_t begin, size_t end, uint32_t* out)> elements;
};

// As draw_vertices, from the arrays (AttribSource::Arrays, no materials): without a program
// each piece of vertices is fetched and transformed at once, while it is in the cache.
void draw_array_vertices(Context& ctx, GLenum mode, const ArrayVertices& vertices, std::span<const uint32_t> indices);

// One vertex through the vertex stage (transform, lighting, every unit's texture matrix):
// the raster position's vertex.
raster::ClipVertex transform_single_vertex(Context& ctx, const raster::VertexInput& vertex);

// The draw snapshot for fragments that do not come from primitives (pixel rectangles,
// bitmaps): the current fragment state with the bound textures.
const raster::DrawState& fragment_snapshot(Context& ctx);

}  // namespace pineda
