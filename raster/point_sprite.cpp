#include "raster/point_sprite.h"

#include <algorithm>
#include <cmath>

#include "raster/draw_record.h"
#include "raster/raster_limits.h"
#include "raster/setup.h"

namespace pineda::raster {

void sprite_coord_planes(float size, bool origin_lower_left, Plane& s, Plane& t) {
  const float step = 1.f / size;
  s = {0.5f, step, 0.f};
  t = {0.5f, 0.f, origin_lower_left ? step : -step};
}

bool setup_point_sprite(const WinVert& v, float size, const PointSprite& sprite, const DrawRecord& draw,
                        const SetupParams& params, PrimSetup& out) {
  // The side in sub-pixels. Coverage is decided in integers, by the fill rule of a square
  // polygon (as llvmpipe draws sprites): pixel i is covered when its centre is in
  // [x - side/2, x + side/2), and likewise in y.
  const float clamped = size >= 1.f ? std::min(size, static_cast<float>(kMaxPointSize)) : 1.f;  // NaN -> 1
  const int64_t side = std::llround(double{clamped} * kSubpixelOne);
  auto first = [&](int64_t c) { return ceil_div(2 * c - side - kSubpixelOne, 2 * kSubpixelOne); };
  auto end = [&](int64_t c) { return ceil_div(2 * c + side - kSubpixelOne, 2 * kSubpixelOne); };
  const PixelRect box{static_cast<int>(first(v.x)), static_cast<int>(first(v.y)), static_cast<int>(end(v.x)),
                      static_cast<int>(end(v.y))};
  out.bounds = intersect(box, params.clip);
  if (out.bounds.empty()) return false;
  out.kind = CoverageKind::Point;
  out.draw = params.draw;
  out.back_facing = params.back_facing;
  for (int i = 0; i < 4; ++i) out.flat_color[i] = params.flat_color[i];
  // Every other value is the vertex's, as for any point.
  out.perspective = false;
  out.ref_x = static_cast<float>(v.fx);
  out.ref_y = static_cast<float>(v.fy);
  out.inv_w = {1.f, 0.f, 0.f};
  for (int k = 0; k < params.planes; ++k) out.planes[k] = {v.attr[k], 0.f, 0.f};
  out.z0 = v.z + params.depth_offset;
  out.dzdx = out.dzdy = 0.0;

  replace_sprite_coords(static_cast<float>(static_cast<double>(side) / kSubpixelOne), sprite, draw, out);
  return true;
}

void replace_sprite_coords(float size, const PointSprite& sprite, const DrawRecord& draw, PrimSetup& out) {
  Plane s, t;
  sprite_coord_planes(size, sprite.origin_lower_left, s, t);
  for (int k = 0; k < draw.num_units; ++k) {
    if (!(sprite.coord_replace >> draw.units[k] & 1u)) continue;
    Plane* tc = &out.planes[draw.tex_plane[k]];
    tc[0] = s;
    tc[1] = t;
    tc[2] = {1.f, 0.f, 0.f};  // q
    if (draw.r_plane[k] >= 0) out.planes[draw.r_plane[k]] = {0.f, 0.f, 0.f};
  }
}

}  // namespace pineda::raster
