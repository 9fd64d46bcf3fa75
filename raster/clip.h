// Homogeneous clipping of polygons and lines, in double precision, with the vertex
// attributes interpolated linearly in clip space.
#pragma once
#include <cstdint>
#include <vector>

#include "raster/texture.h"
#include "raster/vertex.h"
#include "shader/program.h"

namespace pineda::raster {

// colour (4), back colour (4), s, t, r, q per texture unit, secondary colour (3), back
// secondary colour (3), fog coordinate (1).
constexpr int kClipTexAttrs = 8;
constexpr int kClipSecondaryAttrs = kClipTexAttrs + 4 * kMaxTextureUnits;
constexpr int kClipFogAttr = kClipSecondaryAttrs + 6;
constexpr int kClipAttrs = kClipFogAttr + 1;
// A programmable draw carries its varyings in attr[] instead.
constexpr int kClipAttrCapacity = kClipAttrs > shader::kMaxVaryingFloats ? kClipAttrs : shader::kMaxVaryingFloats;

struct ClipVert {
  double pos[4];
  double user[kMaxClipPlanes];  // distances to the user clip planes
  float attr[kClipAttrCapacity];
};

// Points closer than this to w = 0 are clipped away: their projection is meaningless.
constexpr double kMinW = 1e-30;

// The clip volume: near and far always, w > epsilon always, x/y against the guard band
// (expressed as multiples of w, so the band is fixed in window pixels), and the enabled user
// clip planes (ClipVert::user >= 0 is inside).
struct ClipVolume {
  double x_min = -1, x_max = 1, y_min = -1, y_max = 1;
  uint32_t user_planes = 0;  // bit i: user plane i
  int attrs = kClipAttrs;     // how many of ClipVert::attr clipping interpolates
};

// Bit i set when the vertex is outside plane i.
uint32_t clip_outcode(const ClipVert& v, const ClipVolume& vol);

// Clips a convex polygon; `out` receives the visible polygon (empty when nothing is left).
// An edge crossing a plane is always cut from its inside vertex, so that two primitives
// sharing an edge get the same new vertex.
void clip_polygon(const std::vector<ClipVert>& in, const ClipVolume& vol, std::vector<ClipVert>& out,
                  std::vector<ClipVert>& scratch);

// Clips a segment in place; false when nothing is left.
bool clip_line(ClipVert& a, ClipVert& b, const ClipVolume& vol);

}  // namespace pineda::raster
