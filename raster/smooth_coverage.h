// Coverage of antialiased points and lines (GL 1.5 sections 3.3.2 and 3.4.2): the fraction of a
// pixel's square that lies inside the point's disc or the line's rectangle. It is a function of
// the primitive and the pixel only, so every thread count and SIMD path gets the same values.
#pragma once

#include "raster/prim_setup.h"

namespace pineda::raster {

// Area of the unit square [x, x + 1] x [y, y + 1] inside the disc of radius r centred at the origin.
double square_in_disc(double x, double y, double r);

// A line's rectangle in its own frame: the unit vector along it, its middle, and half its
// length and width. Worked out once per line rather than once per pixel.
struct LineFrame {
  double ux, uy;                 // along the line
  double mx, my;                 // the middle
  double half_length, half_width;
  double square_reach;  // how far a unit square reaches from its centre along the line or across it
  double steep, shallow;  // max and min of |ux| and |uy|
  explicit LineFrame(const SmoothShape& line);
};

// Area of the unit square [x, x + 1] x [y, y + 1] inside the line's rectangle: `size` wide,
// from (x0, y0) to (x1, y1) long.
double square_in_rectangle(double x, double y, const LineFrame& line);
inline double square_in_rectangle(double x, double y, const SmoothShape& line) {
  return square_in_rectangle(x, y, LineFrame(line));
}

// Coverage of pixels by the smooth point or line p (p.smooth.size > 0): the exact area of a
// pixel's square inside the point's disc or the line's rectangle.
class SmoothCoverage {
 public:
  explicit SmoothCoverage(const PrimSetup& p);
  double at(int x, int y) const;

 private:
  const SmoothShape& shape_;
  bool point_;
  LineFrame line_;
};

inline double smooth_coverage(const PrimSetup& p, int x, int y) { return SmoothCoverage(p).at(x, y); }

// The coverages of the 2x2 quad at (x, y): pixel i is (x + (i & 1), y + (i >> 1)). Pixels not in
// `mask` (bit i: pixel i) get 1: their coverage is not worked out.
void smooth_quad_coverage(const PrimSetup& p, int x, int y, unsigned mask, float out[4]);

// The pixels whose coverage can be above zero.
PixelRect smooth_bounds(const SmoothShape& s);

// Narrows [x0, x1) to the pixels of row y that a steep line's rectangle can reach.
void smooth_row_span(const SmoothShape& s, int y, int& x0, int& x1);

}  // namespace pineda::raster
