#include "raster/primitive.h"

#include <memory>
#include <vector>

namespace pineda::raster {
namespace {

class VertexSource {
 public:
  VertexSource(std::span<const ClipVertex> vertices, std::span<const uint32_t> indices)
      : vertices_(vertices), indices_(indices) {}
  size_t count() const { return indices_.empty() ? vertices_.size() : indices_.size(); }
  // Null when the index points past the vertex array.
  const ClipVertex* at(size_t i) const {
    const size_t v = indices_.empty() ? i : indices_[i];
    return v < vertices_.size() ? &vertices_[v] : nullptr;
  }

 private:
  std::span<const ClipVertex> vertices_;
  std::span<const uint32_t> indices_;
};

void emit_polygon(PrimitiveSink& sink, std::span<const ClipVertex* const> v, bool use_edge_flags,
                  size_t provoking) {
  bool flags[4];
  for (const ClipVertex* p : v)
    if (!p) return;
  for (size_t i = 0; i < v.size(); ++i) flags[i] = use_edge_flags ? v[i]->edge_flag : true;
  sink.polygon(v, std::span<const bool>(flags, v.size()), *v[provoking]);
}

void assemble_polygon(const VertexSource& src, PrimitiveSink& sink) {
  const size_t n = src.count();
  if (n < 3) return;
  std::vector<const ClipVertex*> v(n);
  for (size_t i = 0; i < n; ++i) {
    v[i] = src.at(i);
    if (!v[i]) return;
  }
  std::unique_ptr<bool[]> flags(new bool[n]);
  for (size_t i = 0; i < n; ++i) flags[i] = v[i]->edge_flag;
  sink.polygon(v, std::span<const bool>(flags.get(), n), *v[0]);
}

void line_if_valid(PrimitiveSink& sink, const ClipVertex* a, const ClipVertex* b) {
  if (a && b) sink.line(*a, *b, *b);
}

}  // namespace

void assemble_primitives(Primitive mode, std::span<const ClipVertex> vertices,
                         std::span<const uint32_t> indices, PrimitiveSink& sink) {
  const VertexSource src(vertices, indices);
  const size_t n = src.count();
  switch (mode) {
    case Primitive::Points:
      for (size_t i = 0; i < n; ++i)
        if (const ClipVertex* v = src.at(i)) sink.point(*v);
      break;
    case Primitive::Lines:
      for (size_t i = 0; i + 1 < n; i += 2) line_if_valid(sink, src.at(i), src.at(i + 1));
      break;
    case Primitive::LineStrip:
    case Primitive::LineLoop:
      for (size_t i = 0; i + 1 < n; ++i) line_if_valid(sink, src.at(i), src.at(i + 1));
      // The closing segment's provoking vertex is the first one (GL 1.5 table 2.12).
      if (mode == Primitive::LineLoop && n >= 2) line_if_valid(sink, src.at(n - 1), src.at(0));
      break;
    case Primitive::Triangles:
      for (size_t i = 0; i + 2 < n; i += 3) {
        const ClipVertex* v[3] = {src.at(i), src.at(i + 1), src.at(i + 2)};
        emit_polygon(sink, v, true, 2);
      }
      break;
    case Primitive::TriangleStrip:
      for (size_t i = 0; i + 2 < n; ++i) {
        // Odd triangles swap their first two vertices to keep a consistent winding.
        const ClipVertex* v[3] = {src.at(i + (i & 1)), src.at(i + 1 - (i & 1)), src.at(i + 2)};
        emit_polygon(sink, v, false, 2);
      }
      break;
    case Primitive::TriangleFan:
      for (size_t i = 1; i + 1 < n; ++i) {
        const ClipVertex* v[3] = {src.at(0), src.at(i), src.at(i + 1)};
        emit_polygon(sink, v, false, 2);
      }
      break;
    case Primitive::Quads:
      for (size_t i = 0; i + 3 < n; i += 4) {
        const ClipVertex* v[4] = {src.at(i), src.at(i + 1), src.at(i + 2), src.at(i + 3)};
        emit_polygon(sink, v, true, 3);
      }
      break;
    case Primitive::QuadStrip:
      for (size_t i = 0; i + 3 < n; i += 2) {
        // Quad q is v[2q], v[2q+1], v[2q+3], v[2q+2]; its provoking vertex is v[2q+3].
        const ClipVertex* v[4] = {src.at(i), src.at(i + 1), src.at(i + 3), src.at(i + 2)};
        emit_polygon(sink, v, false, 2);
      }
      break;
    case Primitive::Polygon:
      assemble_polygon(src, sink);
      break;
  }
}

}  // namespace pineda::raster
