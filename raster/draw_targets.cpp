#include "raster/draw_targets.h"

#include <algorithm>
#include <cstring>

#include "raster/raster_limits.h"

namespace pineda::raster {
namespace {

constexpr int kMaxQuads = kTileSize / 2;  // the longest quad row a tile hands over

// The depth and stencil values of pixels [x0, x1) x [y0, y1), at most two rows of a tile.
struct DepthStencilRows {
  uint32_t depth[2][kTileSize + 2];
  uint8_t stencil[2][kTileSize + 2];
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  bool has_depth = false, has_stencil = false;

  void save(const Framebuffer& fb) {
    for (int y = y0; y < y1; ++y) {
      if (has_depth) std::memcpy(depth[y - y0], fb.depth.base + fb.depth.stride * y + x0, size_t(x1 - x0) * 4);
      if (has_stencil) std::memcpy(stencil[y - y0], fb.stencil.base + fb.stencil.stride * y + x0, size_t(x1 - x0));
    }
  }
  void restore(const Framebuffer& fb) const {
    for (int y = y0; y < y1; ++y) {
      if (has_depth) std::memcpy(fb.depth.base + fb.depth.stride * y + x0, depth[y - y0], size_t(x1 - x0) * 4);
      if (has_stencil) std::memcpy(fb.stencil.base + fb.stencil.stride * y + x0, stencil[y - y0], size_t(x1 - x0));
    }
  }
};

// At most kMaxQuads quads of row y into every draw buffer.
uint32_t targets_row(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                     const uint8_t* masks) {
  const std::vector<DrawRecord>& targets = *d.target_draws;
  DepthStencilRows rows;
  rows.has_depth = d.key.depth && d.state.depth_write;
  rows.has_stencil = d.key.stencil;
  const bool restore = rows.has_depth || rows.has_stencil;
  if (restore) {
    rows.x0 = std::max(x, 0);
    rows.x1 = std::min(x + 2 * count, fb.width);
    rows.y0 = std::max(y, 0);
    rows.y1 = std::min(y + 2, fb.height);
    if (rows.x0 >= rows.x1 || rows.y0 >= rows.y1) return 0;
    rows.save(fb);
  }
  // The first draw buffer with a colour buffer counts the samples; with none at all, one pass
  // without colour still updates depth and stencil.
  int first = -1;
  for (int i = 0; i < int(targets.size()) && first < 0; ++i)
    if (fb.target_color(i).base) first = i;
  if (first < 0) return targets[0].routine(targets[0], p, fb.target(0), x, y, count, masks);
  uint32_t passed = 0;
  for (int i = first; i < int(targets.size()); ++i) {
    if (!fb.target_color(i).base) continue;
    if (i != first && restore) rows.restore(fb);
    const uint32_t n = targets[size_t(i)].routine(targets[size_t(i)], p, fb.target(i), x, y, count, masks);
    if (i == first) passed = n;
  }
  return passed;
}

uint32_t target_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                      const uint8_t* masks) {
  uint32_t passed = 0;
  for (int q = 0; q < count; q += kMaxQuads) {
    const int n = std::min(kMaxQuads, count - q);
    passed += targets_row(d, p, fb, x + 2 * q, y, n, masks + q);
  }
  return passed;
}

}  // namespace

void prepare_target_draws(DrawRecord& draw, const Framebuffer& fb, SimdPath path) {
  auto records = std::make_shared<std::vector<DrawRecord>>();
  for (int i = 0; i < fb.color_targets; ++i) records->push_back(make_draw_record(draw.state, fb.target(i), path, draw.fades_points));
  draw.target_draws = std::move(records);
  draw.routine = target_quads;
}

}  // namespace pineda::raster
