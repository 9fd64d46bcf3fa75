#include "raster/primitive.h"

#include <cmath>
#include <cstdlib>

namespace pineda::raster {
namespace {

class VertexSource {
 public:
  VertexSource(std::span<const ClipVertex> vertices, std::span<const uint32_t> indices, bool edge_flags)
      : vertices_(vertices), indices_(indices), edge_flags_(edge_flags) {}
  size_t count() const { return indices_.empty() ? vertices_.size() : indices_.size(); }
  // Null when the index points past the vertex array.
  const ClipVertex* at(size_t i) const {
    const size_t v = indices_.empty() ? i : indices_[i];
    return v < vertices_.size() ? &vertices_[v] : nullptr;
  }
  // v's edge flag, when the sink reads them (else true, without reading the vertex).
  bool edge(const ClipVertex* v) const { return !edge_flags_ || v->edge_flag; }

 private:
  std::span<const ClipVertex> vertices_;
  std::span<const uint32_t> indices_;
  bool edge_flags_;
};

bool inside_view_volume(const ClipVertex& v) {
  const float w = v.clip[3];
  return std::fabs(v.clip[0]) <= w && std::fabs(v.clip[1]) <= w && std::fabs(v.clip[2]) <= w;
}

// Whether any vertex the draw uses lies outside the view volume. Mesa's draw module then
// takes its clipping path, which splits quads along the other diagonal; following it keeps
// the interpolated colours of quads identical to llvmpipe's.
bool draw_needs_clipping(const VertexSource& src) {
  for (size_t i = 0; i < src.count(); ++i) {
    const ClipVertex* v = src.at(i);
    if (v && !inside_view_volume(*v)) return true;
  }
  return false;
}

// flags[i] marks the edge from v[i] to v[i + 1] as a boundary edge.
void triangle(PrimitiveSink& sink, const ClipVertex* a, const ClipVertex* b, const ClipVertex* c, bool ab, bool bc,
              bool ca, const ClipVertex* provoking) {
  if (!a || !b || !c) return;
  const ClipVertex* v[3] = {a, b, c};
  const bool flags[3] = {ab, bc, ca};
  sink.polygon(v, flags, *provoking);
}

void line_if_valid(PrimitiveSink& sink, const ClipVertex* a, const ClipVertex* b) {
  if (a && b) sink.line(*a, *b, *b);
}

void assemble_quads(const VertexSource& src, bool clipping, PrimitiveSink& sink) {
  for (size_t i = 0; i + 3 < src.count(); i += 4) {
    const ClipVertex *q0 = src.at(i), *q1 = src.at(i + 1), *q2 = src.at(i + 2), *q3 = src.at(i + 3);
    if (!q0 || !q1 || !q2 || !q3) continue;
    if (clipping) {
      triangle(sink, q0, q1, q3, src.edge(q0), false, src.edge(q3), q3);
      triangle(sink, q1, q2, q3, src.edge(q1), src.edge(q2), false, q3);
    } else {
      triangle(sink, q0, q1, q2, src.edge(q0), src.edge(q1), false, q3);
      triangle(sink, q0, q2, q3, false, src.edge(q2), src.edge(q3), q3);
    }
  }
}

// Quad q is s[2q], s[2q+1], s[2q+3], s[2q+2]; its provoking vertex is s[2q+3].
void assemble_quad_strip(const VertexSource& src, bool clipping, PrimitiveSink& sink) {
  for (size_t i = 0; i + 3 < src.count(); i += 2) {
    const ClipVertex *s0 = src.at(i), *s1 = src.at(i + 1), *s2 = src.at(i + 2), *s3 = src.at(i + 3);
    if (!s0 || !s1 || !s2 || !s3) continue;
    if (clipping) {
      triangle(sink, s2, s0, s3, true, false, true, s3);
      triangle(sink, s0, s1, s3, true, true, false, s3);
    } else {
      triangle(sink, s0, s1, s3, true, true, false, s3);
      triangle(sink, s2, s0, s3, true, false, true, s3);
    }
  }
}

// A fan around the first vertex, which is also the provoking one.
void assemble_polygon(const VertexSource& src, PrimitiveSink& sink) {
  const size_t n = src.count();
  if (n < 3) return;
  for (size_t i = 0; i < n; ++i)
    if (!src.at(i)) return;
  const ClipVertex* v0 = src.at(0);
  for (size_t i = 1; i + 1 < n; ++i) {
    const ClipVertex *a = src.at(i), *b = src.at(i + 1);
    triangle(sink, v0, a, b, i == 1 && src.edge(v0), src.edge(a), i + 2 == n && src.edge(b), v0);
  }
}

}  // namespace

void assemble_primitives(Primitive mode, std::span<const ClipVertex> vertices,
                         std::span<const uint32_t> indices, PrimitiveSink& sink) {
  const VertexSource src(vertices, indices, sink.reads_edge_flags());
  const size_t n = src.count();
  switch (mode) {
    case Primitive::Points:
      for (size_t i = 0; i < n; ++i)
        if (const ClipVertex* v = src.at(i)) sink.point(*v);
      break;
    case Primitive::Lines:
      for (size_t i = 0; i + 1 < n; i += 2) {
        sink.restart_line_stipple();
        line_if_valid(sink, src.at(i), src.at(i + 1));
      }
      break;
    case Primitive::LineStrip:
    case Primitive::LineLoop:
      sink.restart_line_stipple();
      for (size_t i = 0; i + 1 < n; ++i) line_if_valid(sink, src.at(i), src.at(i + 1));
      // The closing segment's provoking vertex is the first one (GL 1.5 table 2.12).
      if (mode == Primitive::LineLoop && n >= 2) line_if_valid(sink, src.at(n - 1), src.at(0));
      break;
    case Primitive::Triangles:
      for (size_t i = 0; i + 2 < n; i += 3) {
        const ClipVertex *a = src.at(i), *b = src.at(i + 1), *c = src.at(i + 2);
        if (a && b && c) triangle(sink, a, b, c, src.edge(a), src.edge(b), src.edge(c), c);
      }
      break;
    case Primitive::TriangleStrip:
      for (size_t i = 0; i + 2 < n; ++i) {
        // Odd triangles swap their first two vertices to keep a consistent winding.
        const ClipVertex* c = src.at(i + 2);
        triangle(sink, src.at(i + (i & 1)), src.at(i + 1 - (i & 1)), c, true, true, true, c);
      }
      break;
    case Primitive::TriangleFan:
      for (size_t i = 1; i + 1 < n; ++i) {
        const ClipVertex* c = src.at(i + 1);
        triangle(sink, src.at(0), src.at(i), c, true, true, true, c);
      }
      break;
    case Primitive::Quads:
      assemble_quads(src, draw_needs_clipping(src), sink);
      break;
    case Primitive::QuadStrip:
      assemble_quad_strip(src, draw_needs_clipping(src), sink);
      break;
    case Primitive::Polygon:
      assemble_polygon(src, sink);
      break;
  }
}

}  // namespace pineda::raster
