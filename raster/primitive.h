// Primitive assembly: turns a vertex sequence of one GL mode into points, lines and polygons.
#pragma once
#include <cstdint>
#include <span>

#include "raster/draw_state.h"
#include "raster/vertex.h"

namespace pineda::raster {

class PrimitiveSink {
 public:
  virtual ~PrimitiveSink() = default;
  virtual void point(const ClipVertex& v) = 0;
  // `provoking` is the vertex whose colour flat shading uses.
  virtual void line(const ClipVertex& a, const ClipVertex& b, const ClipVertex& provoking) = 0;
  // A new independent line or line strip begins: the line stipple counter restarts.
  virtual void restart_line_stipple() = 0;
  // A convex polygon (triangle, quad or GL polygon); edge_flags[i] marks the edge from v[i]
  // to v[i + 1] as a boundary edge for the line and point polygon modes.
  virtual void polygon(std::span<const ClipVertex* const> v, std::span<const bool> edge_flags,
                       const ClipVertex& provoking) = 0;
  // False when polygon() ignores the edge flags (then all true): assembly does not read them.
  virtual bool reads_edge_flags() const { return true; }
};

// Indices >= vertices.size() drop the primitives that use them.
void assemble_primitives(Primitive mode, std::span<const ClipVertex> vertices,
                         std::span<const uint32_t> indices, PrimitiveSink& sink);

}  // namespace pineda::raster
