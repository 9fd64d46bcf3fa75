// A primitive after setup: what a tile needs to find its pixels and shade them.
#pragma once
#include <cstddef>
#include <cstdint>

#include "raster/raster_limits.h"
#include "raster/texture.h"

namespace pineda::raster {

constexpr int kColorPlanes = 4;
constexpr int kTexPlanesPerUnit = 3;  // s, t, q
constexpr int kTexRPlanes = 1;        // r, after q, for the units whose texture reads it
constexpr int kSecondaryPlanes = 3;  // r, g, b of the colour sum
constexpr int kFogPlanes = 1;
constexpr int kMaxPlanes = kColorPlanes + (kTexPlanesPerUnit + kTexRPlanes) * kMaxTextureUnits + kSecondaryPlanes + kFogPlanes;

// Pixel rectangle, half-open: [x0, x1) x [y0, y1).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};

inline PixelRect intersect(const PixelRect& a, const PixelRect& b) {
  return {a.x0 > b.x0 ? a.x0 : b.x0, a.y0 > b.y0 ? a.y0 : b.y0, a.x1 < b.x1 ? a.x1 : b.x1,
          a.y1 < b.y1 ? a.y1 : b.y1};
}

// value(x, y) = a0 + dx * (x - ref_x) + dy * (y - ref_y), x and y in pixels.
struct Plane {
  float a0 = 0.f, dx = 0.f, dy = 0.f;
};

// E(px, py) = a * px + b * py + c with px, py in sub-pixels; a pixel centre is inside when
// E >= 0 (the fill-rule bias is folded into c).
struct EdgeFunction {
  int64_t a = 0, b = 0, c = 0;
};

// E at the centre of pixel (x, y).
inline int64_t edge_at(const EdgeFunction& e, int x, int y) {
  return e.a * (int64_t{x} * kSubpixelOne + kSubpixelHalf) + e.b * (int64_t{y} * kSubpixelOne + kSubpixelHalf) + e.c;
}

// A line as GL rasterizes it: along the major axis one span of `width` pixels per column
// (x-major) or row (y-major). Coordinates in sub-pixels.
struct LineCoverage {
  int64_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  int width = 1;
  bool x_major = true;
  int major_min = 0, major_max = -1;  // inclusive range of columns (rows) hit
  // Line stipple, counted as Mesa's draw module does: the pixel whose centre lies d pixels
  // along the major axis from the first vertex (stipple_origin, window pixels; stipple_step
  // the direction) gets pattern index stipple_count + floor(d), d clamped to the segment's
  // [0, stipple_length); stipple_count is the strip's length so far.
  float stipple_origin = 0.f, stipple_length = 0.f, stipple_count = 0.f;
  int stipple_step = 1;
};

// An antialiased point or line: the shape whose area in each pixel is the fragment's coverage
// (raster/smooth_coverage.h). Positions are the snapped ones, in pixels.
struct SmoothShape {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // the point's centre (x0, y0), or the line's ends
  double size = 0;                         // the point's diameter or the line's width; 0: aliased
};

// A multisampled point (GL 1.5 section 3.3.3): the samples inside the disc of diameter `size`
// centred on (x, y) or, a sprite (`square`), those in [x - size/2, x + size/2) in x and in y;
// sub-pixels. size 0: not such a point.
struct SamplePoint {
  int32_t x = 0, y = 0;
  uint32_t size : 31 = 0, square : 1 = 0;  // 16 bytes in all: PrimSetup stays a multiple of 16
  float fade = 1.f;  // point fade (GL 1.4 section 3.3): multiplies the fragment's alpha last
};

enum class CoverageKind : uint8_t { Triangle, Line, Point };

struct PrimSetup {
  CoverageKind kind = CoverageKind::Triangle;
  bool back_facing = false;
  bool perspective = false;  // planes hold a/w and inv_w holds 1/w
  uint32_t draw = 0;         // index of the draw record in the scene
  PixelRect bounds;          // clipped to viewport, scissor and framebuffer

  EdgeFunction edges[3];
  LineCoverage line;
  SmoothShape smooth;
  SamplePoint sample_point;

  float ref_x = 0.f, ref_y = 0.f;
  double z0 = 0.0, dzdx = 0.0, dzdy = 0.0;  // window depth in depth-buffer units
  Plane inv_w;
  // A programmable draw's varyings (DrawState::shader), in the scene's storage; perspective
  // like planes[].
  const Plane* varying_planes = nullptr;
  float flat_color[4] = {0, 0, 0, 0};
  // r, g, b, a, then s, t, q (and r: DrawRecord::r_plane) per enabled unit (in unit order), then the secondary colour and
  // the fog coordinate when the draw uses them (DrawRecord::secondary_plane, fog_plane). Last:
  // the scene copies only the draw's DrawRecord::planes of them (used_bytes).
  Plane planes[kMaxPlanes];
};

// The bytes of a PrimSetup up to its first `planes` planes: all a draw with that many reads.
inline size_t used_bytes(int planes) {
  return offsetof(PrimSetup, planes) + sizeof(Plane) * static_cast<size_t>(planes);
}

}  // namespace pineda::raster
