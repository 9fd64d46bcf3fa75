#pragma once
// Large array draws of independent primitives sent to the renderer in pieces.
#include <cstdint>
#include <span>

#include "state/draw.h"

namespace pineda {

// Vertices (or indices, when given) per piece: a multiple of 1, 2, 3 and 4, so that every
// piece holds whole points, lines, triangles or quads.
inline constexpr size_t kVerticesPerDrawPiece = 12288;

// A draw of GL_POINTS, GL_LINES, GL_TRIANGLES or GL_QUADS in render mode with more than two
// pieces' vertices, with or without a program, goes to draw_array_vertices piece by piece (an
// indexed one with each piece's vertices fetched and transformed once, its indices
// renumbered), as llvmpipe's draw module splits: the vertex stage's output (or a vertex
// shader's) stays a few MiB however large the draw (half a million vertices are 120 MB, whose
// first writes were most of a first frame and whose pass pushed everything else out of the
// caches). The same primitives in the same order, so the same pixels. False, having drawn
// nothing, for other draws.
bool draw_array_vertices_in_pieces(Context& ctx, GLenum mode, const ArrayVertices& vertices,
                                   std::span<const uint32_t> indices);

}  // namespace pineda
