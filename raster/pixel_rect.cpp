#include "raster/pixel_rect.h"

#include <algorithm>
#include <cstring>

#include "raster/blend8.h"
#include "raster/fragment_ops.h"
#include "raster/multisample.h"

namespace pineda::raster {
namespace {

DrawState flat_state(DrawState state) {
  state.flat_shading = true;  // the fragment's colour is the primitive's flat colour
  return state;
}

}  // namespace

PixelFragmentWriter::PixelFragmentWriter(const DrawState& state, const Framebuffer& fb, const float (*texcoords)[4],
                                         float fog_coordinate)
    : record_(make_draw_record(flat_state(state), fb)), fb_(fb) {
  if (record_.fog_plane >= 0) prim_.planes[record_.fog_plane].a0 = fog_coordinate;
  prim_.kind = CoverageKind::Point;
  for (int k = 0; k < record_.num_units; ++k) {
    const float* tc = texcoords[record_.units[k]];
    Plane* planes = &prim_.planes[record_.tex_plane[k]];
    planes[0].a0 = tc[0];
    planes[1].a0 = tc[1];
    planes[2].a0 = tc[3];  // q
    if (record_.r_plane[k] >= 0) prim_.planes[record_.r_plane[k]].a0 = tc[2];
  }
  x1_ = fb.width;
  y1_ = fb.height;
  if (state.scissor_test) {
    x0_ = std::max(x0_, state.scissor.x);
    y0_ = std::max(y0_, state.scissor.y);
    x1_ = std::min<int64_t>(x1_, int64_t{state.scissor.x} + std::max(state.scissor.width, 0));
    y1_ = std::min<int64_t>(y1_, int64_t{state.scissor.y} + std::max(state.scissor.height, 0));
  }
  const FragmentKey& key = record_.key;
  rgba8_rows_ = !state.shader && !key.textured && !key.stencil && (!key.blend || key.blend8 != Blend8::Other) &&
                !key.extras && !key.count_samples && !state.alpha_test && record_.color_write_all && fb.samples == 1 &&
                fb.color_targets <= 1 && fb.color.base && !fb.color.reduction.active;
}

namespace {

using Words = uint32_t __attribute__((vector_size(16)));

// blend8.h's integer blend of four source words over four destination words (both in the
// buffer's byte order: the alpha byte is the top one in either), what the fragment routines'
// blending gives for these factors.
Words blend_words(Blend8 blend, Words src, Words dst) {
  switch (blend) {
    case Blend8::Over: return blend_over_halves(src, dst);
    case Blend8::OverKeepAlpha: return keep_alpha8(blend_over_halves(src, dst), dst);
    case Blend8::AddScaled: return blend_add_scaled8(src, dst);
    case Blend8::Add: return blend_add8(src, dst);
    case Blend8::Other: break;
  }
  return src;
}

}  // namespace

template <typename ColorOf, typename DepthOf>
void PixelFragmentWriter::write_row(int x, int y, int count, ColorOf color_of, DepthOf depth_of) {
  if (y < y0_ || y >= y1_) return;
  const int first = std::max(x, x0_), last = static_cast<int>(std::min<int64_t>(int64_t{x} + count, x1_));
  if (first >= last) return;
  uint8_t* dst = fb_.color.base + fb_.color.stride * y + 4 * static_cast<ptrdiff_t>(first);
  const size_t skip = static_cast<size_t>(first - x), n = static_cast<size_t>(last - first);
  const bool bgra = fb_.color.format == ColorFormat::BGRA8;
  const FragmentKey& key = record_.key;
  if (!key.depth && !key.blend) {
    for (size_t i = 0; i < n; ++i) {
      const uint32_t p = bgra ? swap_red_blue(color_of(skip + i)) : color_of(skip + i);
      std::memcpy(dst + 4 * i, &p, 4);
    }
    return;
  }
  // (Only with the depth test: a draw without one may have no depth buffer.)
  uint32_t* stored = key.depth ? fb_.depth.base + static_cast<ptrdiff_t>(y) * fb_.depth.stride + first : nullptr;
  const DrawState& s = record_.state;
  for (size_t i = 0; i < n; i += 4) {  // four words at a time, the last group padded
    const size_t m = std::min<size_t>(4, n - i);
    // (Whole groups by one 16-byte move: a variable length went through the stack, and the
    // vector load after its narrower stores waited on store forwarding.)
    auto load = [m](Words& words, const void* from) {
      if (m == 4) std::memcpy(&words, from, sizeof words);
      else std::memcpy(&words, from, 4 * m);
    };
    auto store = [m](void* to, const Words& words) {
      if (m == 4) std::memcpy(to, &words, sizeof words);
      else std::memcpy(to, &words, 4 * m);
    };
    // Lanes by a loop of four where the group is whole (built in registers, not on the stack).
    auto lanes = [m, at = skip + i](auto value_of) {
      if (m == 4) return Words{value_of(at), value_of(at + 1), value_of(at + 2), value_of(at + 3)};
      Words words = {};
      for (size_t l = 0; l < m; ++l) words[l] = value_of(at + l);
      return words;
    };
    Words colors = lanes([&](size_t k) { return bgra ? swap_red_blue(color_of(k)) : color_of(k); }), old = {};
    load(old, dst + 4 * i);
    if (key.blend) colors = blend_words(key.blend8, colors, old);
    if (key.depth) {
      const Words z = lanes(depth_of);
      Words depths = {};
      load(depths, stored + i);
      const Words pass = compare_lanes(s.depth_func, z, depths);
      colors = pass ? colors : old;
      if (s.depth_write) store(stored + i, pass ? z : depths);
    }
    store(dst + 4 * i, colors);
  }
}

namespace {

// The quad routines' depth of a constant plane (block_depth_body.inc's flat_depth) of a depth
// in [0, 1] (clamped here), for a buffer whose largest value is depth_max.
uint32_t stored_depth(double d, double depth_max) {
  return static_cast<uint32_t>((d > 0.0 ? (d < 1.0 ? d : 1.0) : 0.0) * depth_max + 0.5);
}

}  // namespace

void PixelFragmentWriter::rgba8_row(int x, int y, const uint32_t* rgba, int count, double depth) {
  if (!record_.key.depth && !record_.key.blend && fb_.color.format == ColorFormat::RGBA8) {  // a copy
    if (y < y0_ || y >= y1_) return;
    const int first = std::max(x, x0_), last = static_cast<int>(std::min<int64_t>(int64_t{x} + count, x1_));
    if (first < last)
      std::memcpy(fb_.color.base + fb_.color.stride * y + 4 * static_cast<ptrdiff_t>(first), rgba + (first - x),
                  4 * static_cast<size_t>(last - first));
    return;
  }
  const uint32_t z = stored_depth(depth, record_.depth_max);
  write_row(x, y, count, [&](size_t i) { return rgba[i]; }, [&](size_t) { return z; });
}

void PixelFragmentWriter::depth_row(int x, int y, uint32_t rgba, const double* depths, int count) {
  write_row(x, y, count, [&](size_t) { return rgba; }, [&](size_t i) { return stored_depth(depths[i], record_.depth_max); });
}

void PixelFragmentWriter::fragment(int x, int y, const float rgba[4], double depth) {
  if (!inside(x, y)) return;
  for (int c = 0; c < 4; ++c) prim_.flat_color[c] = clamp01(rgba[c]);
  prim_.z0 = (depth > 0.0 ? (depth < 1.0 ? depth : 1.0) : 0.0) * record_.depth_max;
  const uint8_t mask = static_cast<uint8_t>(1u << ((x & 1) + 2 * (y & 1)));
  uint32_t passed = 0;
  for (int sample = 0; sample < fb_.samples; ++sample) {  // every sample of a multisampled pixel
    const Framebuffer plane = fb_.samples > 1 ? sample_plane(fb_, sample) : fb_;
    passed += record_.routine(record_, prim_, plane, x & ~1, y & ~1, 1, &mask);
  }
  if (passed) record_.state.sample_counter->passed.fetch_add(passed, std::memory_order_relaxed);  // occlusion query
}

void PixelFragmentWriter::depth(int x, int y, double z) {
  if (!inside(x, y) || !fb_.depth.base || fb_.depth.bits == 0) return;
  const double clamped = z > 0.0 ? (z < 1.0 ? z : 1.0) : 0.0;
  for (int sample = 0; sample < fb_.samples; ++sample)
    fb_.depth.base[fb_.depth.sample_stride * sample + static_cast<ptrdiff_t>(y) * fb_.depth.stride + x] =
        static_cast<uint32_t>(clamped * record_.depth_max + 0.5);
}

void PixelFragmentWriter::stencil(int x, int y, uint32_t value) {
  if (!inside(x, y) || !fb_.stencil.base || fb_.stencil.bits == 0) return;
  const uint8_t mask = record_.state.stencil_front.write_mask;
  for (int sample = 0; sample < fb_.samples; ++sample) {
    uint8_t& s = fb_.stencil.base[fb_.stencil.sample_stride * sample + static_cast<ptrdiff_t>(y) * fb_.stencil.stride + x];
    s = static_cast<uint8_t>((s & ~mask) | (value & mask));
  }
}

}  // namespace pineda::raster
