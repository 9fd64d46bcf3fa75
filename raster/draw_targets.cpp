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

// pass(i) for every draw buffer i with a colour buffer (for draw buffer 0 alone when none has
// one: depth and stencil are still updated), at most kMaxQuads quads of row y from x, the depth
// and stencil of each of `planes` (one, or each sample's) restored between the passes. Returns
// the first pass's count of samples.
template <class Pass>
uint32_t each_target(const DrawRecord& d, const Framebuffer* planes, int plane_count, int x, int y, int count,
                     const Pass& pass) {
  const std::vector<DrawRecord>& targets = *d.target_draws;
  const Framebuffer& fb = planes[0];
  DepthStencilRows rows[kMaxSamples];
  const bool restore = (d.key.depth && d.state.depth_write) || d.key.stencil;
  if (restore) {
    for (int k = 0; k < plane_count; ++k) {
      DepthStencilRows& r = rows[k];
      r.has_depth = d.key.depth && d.state.depth_write;
      r.has_stencil = d.key.stencil;
      r.x0 = std::max(x, 0);
      r.x1 = std::min(x + 2 * count, fb.width);
      r.y0 = std::max(y, 0);
      r.y1 = std::min(y + 2, fb.height);
      if (r.x0 >= r.x1 || r.y0 >= r.y1) return 0;
      r.save(planes[k]);
    }
  }
  int first = -1;
  for (int i = 0; i < int(targets.size()) && first < 0; ++i)
    if (fb.target_color(i).base) first = i;
  if (first < 0) return pass(0);
  uint32_t passed = 0;
  for (int i = first; i < int(targets.size()); ++i) {
    if (!fb.target_color(i).base) continue;
    if (i != first && restore)
      for (int k = 0; k < plane_count; ++k) rows[k].restore(planes[k]);
    const uint32_t n = pass(i);
    if (i == first) passed = n;
  }
  return passed;
}

// At most kMaxQuads quads of row y into every draw buffer.
uint32_t targets_row(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                     const uint8_t* masks) {
  const std::vector<DrawRecord>& targets = *d.target_draws;
  return each_target(d, &fb, 1, x, y, count, [&](int i) {
    return targets[size_t(i)].routine(targets[size_t(i)], p, fb.target(i), x, y, count, masks);
  });
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

// A multisampled draw's quads (sample_targets.h, at most kMaxQuads) into every draw buffer:
// each draw buffer's record shades them once for all samples, into each sample's view of it.
uint32_t target_sample_quads(const DrawRecord& d, const PrimSetup& p, const SampleTargets& t, int x, int y, int count,
                             const uint16_t* masks) {
  Framebuffer planes[kMaxSamples];
  int plane_count = 0;
  for (int s = 0; s < kMaxSamples; ++s)
    if (t.draw[s]) planes[plane_count++] = t.plane[s];
  if (!plane_count) return 0;
  return each_target(d, planes, plane_count, x, y, count, [&](int i) {
    SampleTargets target;
    for (int s = 0; s < kMaxSamples; ++s) {
      if (!t.draw[s]) continue;
      target.draw[s] = &(*t.draw[s]->target_draws)[size_t(i)];
      target.prim[s] = t.prim[s];
      target.plane[s] = t.plane[s].target(i);
    }
    const DrawRecord& record = (*d.target_draws)[size_t(i)];
    return record.sample_routine(record, p, target, x, y, count, masks);
  });
}

}  // namespace

void prepare_target_draws(DrawRecord& draw, const Framebuffer& fb, SimdPath path) {
  auto records = std::make_shared<std::vector<DrawRecord>>();
  for (int i = 0; i < fb.color_targets; ++i) records->push_back(make_draw_record(draw.state, fb.target(i), path, draw.fades_points));
  draw.target_draws = std::move(records);
  draw.routine = target_quads;
  const bool every_target_shades_once = std::all_of(draw.target_draws->begin(), draw.target_draws->end(),
                                                    [](const DrawRecord& t) { return t.sample_routine; });
  draw.sample_routine = fb.samples > 1 && every_target_shades_once ? target_sample_quads : nullptr;
}

}  // namespace pineda::raster
