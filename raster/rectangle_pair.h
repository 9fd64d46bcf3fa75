// Two filled triangles that make one axis-aligned rectangle (a sprite, a glyph, a full-screen
// pass: a quad drawn as two triangles), rasterized as the rectangle: rows of whole quads, none
// split along the diagonal and shaded twice. Mesa's llvmpipe does the same (lp_setup_rect.c).
// The rectangle covers exactly the pixels the two triangles cover (the fill rule gives a centre
// on the shared diagonal to one of them), and it takes the first triangle's planes: only when
// the values at the four corners lie on one plane, and with one depth and one 1/w at all four,
// so that its depths are the triangles' (the invariance of multipass rendering).
#pragma once
#include <cstdint>

#include "raster/prim_setup.h"
#include "raster/setup.h"

namespace pineda::raster {

// A triangle whose legs run along the axes, held back until the next triangle says whether it
// completes the rectangle: its vertices (positions and the values the draw interpolates), its
// right angle's vertex and the rectangle's corners in sub-pixels.
struct RectangleHalf {
  WinVert v[3];
  int corner = 0;
  int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

// Whether two vertices share an x and two a y: rectangle_corner's test, inline for the many
// triangles that fail it (a mesh's: the call was 1% of glsl_skinned).
inline bool may_be_rectangle_half(const WinPosition& a, const WinPosition& b, const WinPosition& c) {
  return (a.x == b.x || b.x == c.x || c.x == a.x) && (a.y == b.y || b.y == c.y || c.y == a.y);
}

// Whether the triangle is half of an axis-aligned rectangle (one vertex shares its x with
// another and its y with the third, at a non-zero distance); sets `corner` and the box then.
bool rectangle_corner(const WinPosition& a, const WinPosition& b, const WinPosition& c, int& corner, int64_t& x0,
                      int64_t& y0, int64_t& x1, int64_t& y1);

// Whether the triangle v, whose vertex i interpolates the `count` floats at values[i],
// completes `half` (whose vertex i has them at half_values[i]) into its rectangle: the same
// box and its right angle opposite, the two other vertices equal to the half's, the unsnapped
// positions a rectangle too, one depth and one 1/w at all four corners, and every value with
// equal differences along both pairs of opposite sides.
bool completes_rectangle(const RectangleHalf& half, const float* const (&half_values)[3],
                         const WinPosition* const (&v)[3], const float* const (&values)[3], int count);

// A triangle's setup (of either half) made the rectangle's: the pixels whose centres lie in
// [x0, x1) x [y0, y1) (GL's fill rule on its four sides), inside `clip`, each edge covering all.
void make_rectangle(const RectangleHalf& half, const PixelRect& clip, PrimSetup& prim);

}  // namespace pineda::raster
