#include "state/vertex_arrays/draw_in_pieces.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "state/context.h"

namespace pineda {
namespace {

bool splits(const Context& ctx, GLenum mode, size_t count) {
  return count > 2 * kVerticesPerDrawPiece && ctx.render_mode.mode == GL_RENDER &&
         (mode == GL_POINTS || mode == GL_LINES || mode == GL_TRIANGLES || mode == GL_QUADS);
}

// The vertices of `from` at `elements` (positions in `from`), in that order; consecutive
// positions are fetched together.
ArrayVertices gathered(const ArrayVertices& from, const std::vector<uint32_t>& elements) {
  auto runs = [&from, &elements](size_t begin, size_t end, auto each_run) {
    for (size_t k = begin; k < end;) {
      size_t n = 1;
      while (k + n < end && elements[k + n] == elements[k] + n) ++n;
      each_run(elements[k], n, k - begin);
      k += n;
    }
  };
  return {elements.size(),
          [&from, runs](size_t begin, size_t end, raster::VertexInput* out) {
            runs(begin, end, [&](size_t first, size_t n, size_t at) { from.fetch(first, first + n, out + at); });
          },
          [&from, runs](size_t begin, size_t end, uint32_t* out) {
            runs(begin, end, [&](size_t first, size_t n, size_t at) { from.elements(first, first + n, out + at); });
          }};
}

}  // namespace

bool draw_array_vertices_in_pieces(Context& ctx, GLenum mode, const ArrayVertices& vertices,
                                   std::span<const uint32_t> indices) {
  if (!splits(ctx, mode, indices.empty() ? vertices.count : indices.size())) return false;
  if (indices.empty()) {
    for (size_t begin = 0; begin < vertices.count; begin += kVerticesPerDrawPiece) {
      const size_t n = std::min(kVerticesPerDrawPiece, vertices.count - begin);
      const ArrayVertices piece{
          n, [&vertices, begin](size_t b, size_t e, raster::VertexInput* out) { vertices.fetch(begin + b, begin + e, out); },
          [&vertices, begin](size_t b, size_t e, uint32_t* out) { vertices.elements(begin + b, begin + e, out); }};
      draw_array_vertices(ctx, mode, piece, {});
    }
    return true;
  }
  // Each piece's vertices in the order its indices first name them; an index past the
  // vertices stays past the piece's (the renderer's rule for it applies unchanged).
  constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();
  std::vector<uint32_t> slot(vertices.count, kNone), elements, local;
  for (size_t begin = 0; begin < indices.size(); begin += kVerticesPerDrawPiece) {
    const size_t n = std::min(kVerticesPerDrawPiece, indices.size() - begin);
    elements.clear();
    local.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const uint32_t v = indices[begin + i];
      if (v >= vertices.count) {
        local[i] = kNone;
        continue;
      }
      if (slot[v] == kNone) {
        slot[v] = static_cast<uint32_t>(elements.size());
        elements.push_back(v);
      }
      local[i] = slot[v];
    }
    draw_array_vertices(ctx, mode, gathered(vertices, elements), local);
    for (const uint32_t v : elements) slot[v] = kNone;
  }
  return true;
}

}  // namespace pineda
