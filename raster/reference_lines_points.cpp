#include "raster/reference_lines_points.h"

#include "raster/float_modes.h"
#include "raster/fragment_extras.h"
#include "raster/raster_limits.h"
#include "raster/reference_fragment.h"
#include "raster/smooth_coverage.h"
#include "raster/tile_raster.h"

namespace pineda::raster {

uint64_t reference_lines_points(const PrimSetup& prim, const DrawRecord& draw, const Framebuffer& fb) {
  const PixelRect& b = prim.bounds;
  if (b.empty()) return 0;
  uint64_t passed = 0;
  // The modes a tile runs the draw under (Scene::run_tile): shaders expect them set.
  const ScopedFloatModes modes(draw.state.shader ? kShaderFloatModes : kDefaultFloatModes);
  // The tile rasterizer's line masks are one tile wide.
  for (int ty = b.y0 >> kTileShift; ty <= (b.y1 - 1) >> kTileShift; ++ty)
    for (int tx = b.x0 >> kTileShift; tx <= (b.x1 - 1) >> kTileShift; ++tx) {
      const PixelRect tile{tx * kTileSize, ty * kTileSize, (tx + 1) * kTileSize, (ty + 1) * kTileSize};
      passed += rasterize_in_tile(prim, draw, fb, tile);
    }
  if (passed && draw.state.sample_counter) draw.state.sample_counter->passed.fetch_add(passed);
  return passed;
}

uint32_t reference_plane_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                               const uint8_t* masks) {
  uint32_t passed = 0;
  auto eval = [](const Plane& pl, double ox, double oy) { return pl.a0 + pl.dx * ox + pl.dy * oy; };
  for (int k = 0; k < count; ++k) {
    if (!masks[k]) continue;
    ReferenceQuad q;
    q.x = x + 2 * k;
    q.y = y;
    q.mask = d.key.extras ? masks[k] & stipple_mask(d, p, q.x, y) : masks[k];
    if (!q.mask) continue;
    for (int i = 0; i < 4; ++i) {
      const double ox = q.x + (i & 1) + 0.5 - p.ref_x, oy = q.y + (i >> 1) + 0.5 - p.ref_y;
      q.z[i] = p.z0 + p.dzdx * ox + p.dzdy * oy;
      const double w = p.perspective ? 1.0 / eval(p.inv_w, ox, oy) : 1.0;
      for (int a = 0; a < d.planes; ++a) q.attr[a][i] = eval(p.planes[a], ox, oy) * w;
      if (p.smooth.size > 0.0) q.coverage[i] = smooth_coverage(p, q.x + (i & 1), q.y + (i >> 1));
      q.coverage[i] *= p.sample_point.fade;
    }
    passed += reference_shade_quad(d, p.back_facing, p.flat_color, fb, q);
  }
  return passed;
}

}  // namespace pineda::raster
