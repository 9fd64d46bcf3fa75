// Setup: from window-space vertices to the coverage and interpolation data of a primitive.
#pragma once
#include <cstdint>

#include "raster/prim_setup.h"

namespace pineda::raster {

// A vertex in window space, snapped to sub-pixels: all a programmable draw's setup reads.
struct WinPosition {
  int64_t x = 0, y = 0;  // sub-pixels: decide coverage
  double fx = 0, fy = 0;  // pixels, before snapping: anchor the interpolation planes
  double z = 0.0;        // window depth in depth-buffer units
  double inv_w = 1.0;
  const float* varyings = nullptr;  // a programmable draw's SetupParams::varyings values
};

// With the fixed-function attributes, in PrimSetup plane order.
struct WinVert : WinPosition {
  float attr[kMaxPlanes] = {};
};

struct SetupParams {
  uint32_t draw = 0;
  PixelRect clip;   // viewport ∩ scissor ∩ framebuffer
  bool sample_bounds = false;  // multisampled: a triangle's bounds hold every pixel it overlaps
  int planes = 4;   // how many of attr[] are interpolated
  bool flat = false;
  float flat_color[4] = {0, 0, 0, 0};
  bool back_facing = false;
  // A programmable draw: the inverse-w plane holds 1/w (gl_FragCoord.w) whatever the varyings.
  // (Beside the other flags: one more 8-byte word turned the struct's zeroing into rep stos.)
  bool programmable = false;
  double depth_offset = 0.0;  // added to window depth (polygon offset), depth-buffer units
  // A programmable draw: planes of the `varyings` floats of WinVert::varyings, into
  // varying_out (the scene stores them; PrimSetup::varying_planes points at them).
  int varyings = 0;
  Plane* varying_out = nullptr;
};
// Made once per primitive: GCC 12 zeroes a larger one with `rep stos`, whose start-up cost was
// a tenth of small_tris's setup.
static_assert(sizeof(SetupParams) <= 80);

// Twice the signed area in sub-pixels squared; positive when counter-clockwise (y up).
int64_t signed_area2(const WinPosition& a, const WinPosition& b, const WinPosition& c);

// Depth slopes of the triangle's plane, per pixel, for polygon offset.
bool depth_slopes(const WinVert& a, const WinVert& b, const WinVert& c, double& dzdx, double& dzdy);

// false when the primitive covers no pixel. `Vertex`: WinVert, or WinPosition for a draw
// without fixed-function planes (SetupParams::planes 0: a programmable draw).
template <typename Vertex>
bool setup_triangle(const Vertex& a, const Vertex& b, const Vertex& c, const SetupParams& params, PrimSetup& out);
extern template bool setup_triangle(const WinVert&, const WinVert&, const WinVert&, const SetupParams&, PrimSetup&);
extern template bool setup_triangle(const WinPosition&, const WinPosition&, const WinPosition&, const SetupParams&,
                                    PrimSetup&);
bool setup_line(const WinVert& a, const WinVert& b, int width, const SetupParams& params, PrimSetup& out);
bool setup_point(const WinVert& v, int size, const SetupParams& params, PrimSetup& out);
// Antialiased: a rectangle `width` wide between the ends, a disc of diameter `size` (pixels).
bool setup_smooth_line(const WinVert& a, const WinVert& b, double width, const SetupParams& params, PrimSetup& out);
bool setup_smooth_point(const WinVert& v, double size, const SetupParams& params, PrimSetup& out);
// Multisampled (raster/sample_point.h): the samples inside a disc of diameter `size` or, `square`,
// a square of side `size` (sub-pixels).
bool setup_sample_point(const WinVert& v, int64_t size, bool square, const SetupParams& params, PrimSetup& out);

// Floor division and its ceiling counterpart, for any signs (b > 0).
inline int64_t floor_div(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
inline int64_t ceil_div(int64_t a, int64_t b) { return -floor_div(-a, b); }

}  // namespace pineda::raster
