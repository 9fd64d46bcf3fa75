// Fragments that come from pixel rectangles and bitmaps (glDrawPixels, glCopyPixels,
// glBitmap) rather than from primitives: each has its own colour and depth, and all share
// the raster position's texture coordinates. They go through the same fragment routines as
// primitives (texturing, alpha, stencil, depth, blending or logic op, masks), after the
// scissor test. The caller flushes queued primitives first, so that the order holds.
#pragma once
#include <cstdint>

#include "raster/draw_record.h"
#include "raster/draw_state.h"
#include "raster/framebuffer.h"

namespace pineda::raster {

class PixelFragmentWriter {
 public:
  // texcoords: s, t, r, q of every texture unit; fog_coordinate: the raster distance.
  PixelFragmentWriter(const DrawState& state, const Framebuffer& fb, const float (*texcoords)[4],
                      float fog_coordinate);

  // One fragment at pixel (x, y); colour components and depth in [0, 1] (clamped here).
  void fragment(int x, int y, const float rgba[4], double depth);

  // Writes `value` to the stencil buffer at (x, y), under the scissor test and the front
  // stencil write mask only (glDrawPixels of GL_STENCIL_INDEX).
  void stencil(int x, int y, uint32_t value);

  // Writes depth `z` (in [0, 1], clamped) at (x, y) under the scissor test only: GL_DEPTH_STENCIL
  // pixel rectangles write depth and stencil directly, whatever the depth test (as Mesa).
  void depth(int x, int y, double z);

  // Whether fragments reach the colour buffer unchanged but for the depth test and an integer
  // blend (blend8.h): no shader, texturing, colour sum, fog, alpha or stencil test, other
  // blending, logic op, colour mask or occlusion query, one single-sampled RGBA8 or BGRA8 target
  // that keeps all its bits. Then rgba8_row and depth_row write what fragment() would (a
  // component byte k given as k / 255 is stored as k; a float c as the routines round
  // clamp01(c) * 255).
  bool writes_rgba8_rows() const { return rgba8_rows_; }
  // Fragments (x, y) .. (x + count - 1, y) of colour RGBA8 words (R in the lowest byte) and
  // depth `depth` (in [0, 1], clamped here), the parts inside the framebuffer and the scissor
  // rectangle. Only when writes_rgba8_rows().
  void rgba8_row(int x, int y, const uint32_t* rgba, int count, double depth);
  // The same with one colour and a depth per fragment (glDrawPixels of GL_DEPTH_COMPONENT).
  void depth_row(int x, int y, uint32_t rgba, const double* depths, int count);

  // Whether (x, y) is inside the framebuffer and the scissor rectangle.
  bool inside(int x, int y) const { return x >= x0_ && x < x1_ && y >= y0_ && y < y1_; }

 private:
  DrawRecord record_;
  const Framebuffer& fb_;
  PrimSetup prim_;
  int x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;
  bool rgba8_rows_ = false;

  // Fragments x .. x + count - 1 of row y (inside the framebuffer and scissor rectangle) of colour
  // color_of(i) and stored depth depth_of(i) for i from 0 at x.
  template <typename ColorOf, typename DepthOf>
  void write_row(int x, int y, int count, ColorOf color_of, DepthOf depth_of);
};

}  // namespace pineda::raster
