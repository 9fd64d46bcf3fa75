#include "raster/multisample.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>

#include "raster/color_reduction.h"
#include "raster/raster_limits.h"
#include "raster/tile_raster.h"

namespace pineda::raster {

Framebuffer sample_plane(const Framebuffer& fb, int sample) {
  Framebuffer plane = fb;
  plane.samples = 1;
  if (plane.color.base) plane.color.base += fb.color.sample_stride * sample;
  for (int i = 1; i < fb.color_targets; ++i) {
    ColorBuffer& more = plane.more_color[static_cast<size_t>(i - 1)];
    if (more.base) more.base += more.sample_stride * sample;
  }
  if (plane.depth.base) plane.depth.base += fb.depth.sample_stride * sample;
  if (plane.stencil.base) plane.stencil.base += fb.stencil.sample_stride * sample;
  return plane;
}

uint32_t sample_coverage_mask(const MultisampleState& ms, int samples) {
  const uint32_t all = (1u << samples) - 1;
  if (!ms.sample_coverage) return all;
  const int n = static_cast<int>(std::nearbyint(ms.coverage_value * samples));
  const uint32_t mask = (1u << n) - 1;
  return ms.coverage_invert ? all & ~mask : mask;
}

const DrawRecord& sample_draw(const DrawRecord& draw, int sample) {
  return draw.sample_draws ? (*draw.sample_draws)[sample] : draw;
}

bool may_fade_points(const DrawState& state, Primitive mode) {
  const bool polygons = mode >= Primitive::Triangles;
  const bool points = mode == Primitive::Points ||
                      (polygons && (state.polygon_front == PolygonMode::Point || state.polygon_back == PolygonMode::Point));
  if (!points || !state.multisample.multisample) return false;
  const PointParameters& p = state.point_params;
  const float smallest = p.per_vertex() ? p.size_min : derived_point_size(p, state.point_size, 0.f);
  return !(smallest >= p.fade_threshold);
}

namespace {

// A sample's alpha-to-coverage threshold, on its record and on its draw buffers' records.
void set_coverage_alpha(DrawRecord& record, float min) {
  record.alpha_to_coverage = true;
  record.coverage_alpha_min = min;
  if (!record.target_draws) return;
  auto targets = std::make_shared<std::vector<DrawRecord>>(*record.target_draws);
  for (DrawRecord& target : *targets) set_coverage_alpha(target, min);
  record.target_draws = std::move(targets);
}

}  // namespace

void prepare_sample_draws(DrawRecord& draw, const Framebuffer& fb, SimdPath path) {
  const MultisampleState& ms = draw.state.multisample;
  if (!ms.multisample) return;  // GL 1.5 3.2.1: the multisample fragment operations are off too
  draw.sample_mask = sample_coverage_mask(ms, fb.samples);
  // Alpha to coverage keeps round(alpha * samples) samples: sample s when alpha >= (s + 1/2) /
  // samples, an alpha test per sample, passed besides the application's own (GL 1.5 4.1.3 and
  // 4.1.4: the same alpha decides both).
  if (!ms.alpha_to_coverage) return;
  auto records = std::make_shared<std::vector<DrawRecord>>();
  for (int s = 0; s < fb.samples; ++s) {
    DrawState state = draw.state;
    if (!state.alpha_test) {
      state.alpha_test = true;
      state.alpha_func = CompareFunc::Always;
    }
    records->push_back(make_draw_record(state, fb, path, draw.fades_points));
    records->back().sample_mask = draw.sample_mask;
    set_coverage_alpha(records->back(), (s + 0.5f) / static_cast<float>(fb.samples));
  }
  draw.sample_draws = std::move(records);
}

void apply_clear_samples(const ClearRecord& clear, const Framebuffer& fb, const PixelRect& tile) {
  for (int s = 0; s < fb.samples; ++s) apply_clear(clear, sample_plane(fb, s), tile);
}

namespace {

// A primitive moved to a sample: its edges, sample point and depth taken at the sample's offset
// (the pixel centre then tests the sample), so that the pixel-centre rasterizer finds the
// sample's coverage. Only the setup before the planes is written: `moved` keeps its own planes.
void move_to_sample(const PrimSetup& prim, SampleOffset o, PrimSetup& moved) {
  std::memcpy(static_cast<void*>(&moved), &prim, offsetof(PrimSetup, planes));
  for (int e = 0; e < 3; ++e) moved.edges[e].c = prim.edges[e].c + prim.edges[e].a * o.dx + prim.edges[e].b * o.dy;
  moved.sample_point.x = prim.sample_point.x - o.dx;
  moved.sample_point.y = prim.sample_point.y - o.dy;
  moved.z0 = prim.z0 + (prim.dzdx * o.dx + prim.dzdy * o.dy) / kSubpixelOne;
}

// Stippled lines, pixel rectangles and GL_MULTISAMPLE off cover a sample where they cover the
// pixel centre; other primitives are moved to each sample.
bool covers_samples(const PrimSetup& prim, const DrawRecord& draw) {
  const bool sample_shape = (prim.kind == CoverageKind::Triangle && prim.smooth.size == 0.0) || prim.sample_point.size > 0;
  return sample_shape && draw.state.multisample.multisample;
}

// The draws whose routine shades each sample plane again (DrawRecord::sample_routine null).
uint64_t rasterize_each_plane(const PrimSetup& prim, const DrawRecord& draw, const Framebuffer& fb,
                              const PixelRect& tile) {
  const bool per_sample = covers_samples(prim, draw);
  uint64_t passed = 0;
  PrimSetup shifted;
  if (per_sample) shifted = prim;
  for (int s = 0; s < fb.samples; ++s) {
    if (!((draw.sample_mask >> s) & 1)) continue;
    if (per_sample) move_to_sample(prim, kSampleOffsets4x[s], shifted);
    passed += rasterize_in_tile(per_sample ? shifted : prim, sample_draw(draw, s), sample_plane(fb, s), tile);
  }
  return passed;
}

}  // namespace

uint64_t rasterize_samples_in_tile(const PrimSetup& prim, const DrawRecord& draw, const Framebuffer& fb,
                                   const PixelRect& tile) {
  if (!draw.sample_routine) return rasterize_each_plane(prim, draw, fb, tile);
  const PixelRect area = intersect(prim.bounds, tile);
  if (area.empty()) return 0;
  const bool per_sample = covers_samples(prim, draw);
  TileSampleMasks masks;
  masks.x0 = tile.x0 & ~1;
  masks.y0 = tile.y0 & ~1;
  const int q0 = (area.x0 - masks.x0) / 2, q1 = (area.x1 - 1 - masks.x0) / 2;
  const int r0 = (area.y0 - masks.y0) / 2, r1 = (area.y1 - 1 - masks.y0) / 2;
  for (int r = r0; r <= r1; ++r) std::fill(&masks.quads[r][q0], &masks.quads[r][q1] + 1, uint16_t{0});
  SampleTargets targets;
  PrimSetup moved[kMaxSamples];
  for (int s = 0; s < fb.samples; ++s) {
    if (!((draw.sample_mask >> s) & 1)) continue;
    targets.draw[s] = &sample_draw(draw, s);
    targets.plane[s] = sample_plane(fb, s);
    targets.prim[s] = &prim;
    if (per_sample) {
      move_to_sample(prim, kSampleOffsets4x[s], moved[s]);
      targets.prim[s] = &moved[s];
    }
    add_sample_masks(*targets.prim[s], area, s, masks);
  }
  uint64_t passed = 0;
  for (int r = r0; r <= r1; ++r) {
    int first = q0, last = q1;  // the row's covered quads
    while (first <= last && !masks.quads[r][first]) ++first;
    while (last >= first && !masks.quads[r][last]) --last;
    if (first > last) continue;
    passed += draw.sample_routine(draw, prim, targets, masks.x0 + 2 * first, masks.y0 + 2 * r, last - first + 1,
                                  &masks.quads[r][first]);
  }
  return passed;
}

void resolve_rgba8(const Framebuffer& fb, int x, int y, uint8_t out[4]) {
  unsigned sum[4] = {0, 0, 0, 0};
  for (int s = 0; s < fb.samples; ++s) {
    uint8_t rgba[4];
    read_rgba8(fb.color, fb.color.base + fb.color.sample_stride * s + fb.color.stride * y + 4 * x, rgba);
    for (int c = 0; c < 4; ++c) sum[c] += rgba[c];
  }
  const unsigned n = static_cast<unsigned>(fb.samples);
  for (int c = 0; c < 4; ++c) out[c] = static_cast<uint8_t>((sum[c] + n / 2) / n);
}

void resolve_rgba8_row(const Framebuffer& fb, int x, int y, int n, uint8_t* out) {
  const ColorBuffer& cb = fb.color;
  if (cb.reduction.active || fb.samples != kMaxSamples) {
    for (int i = 0; i < n; ++i) resolve_rgba8(fb, x + i, y, out + 4 * i);
    return;
  }
  // The bytes of the four planes averaged as they lie (a loop the compiler vectorizes), then
  // BGRA8's red and blue swapped into place.
  const uint8_t* in = cb.base + cb.stride * y + 4 * x;
  const ptrdiff_t plane = cb.sample_stride;
  for (int i = 0; i < 4 * n; ++i) {
    const unsigned sum = unsigned{in[i]} + in[plane + i] + in[2 * plane + i] + in[3 * plane + i];
    out[i] = static_cast<uint8_t>((sum + 2) >> 2);
  }
  if (cb.format == ColorFormat::BGRA8)
    for (int i = 0; i < n; ++i) std::swap(out[4 * i], out[4 * i + 2]);
}

void resolve_color(const Framebuffer& fb, const ColorBuffer& out) {
  const unsigned n = static_cast<unsigned>(fb.samples);
  for (int y = 0; y < fb.height; ++y) {
    const uint8_t* in = fb.color.base + fb.color.stride * y;
    uint8_t* row = out.base + out.stride * y;
    for (int i = 0; i < fb.width * 4; ++i) {
      unsigned sum = 0;
      for (int s = 0; s < fb.samples; ++s) sum += in[fb.color.sample_stride * s + i];
      row[i] = static_cast<uint8_t>((sum + n / 2) / n);
    }
  }
}

}  // namespace pineda::raster
