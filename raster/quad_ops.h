// The per-fragment operations on a 2x2 quad after shading: depth and stencil tests, blending
// or logic op, colour masks and the write into an RGBA8/BGRA8 buffer. Shared by the
// fixed-function routines (fragment_pipeline.cpp) and the fragment-shader routine
// (shader_quads.cpp).
#pragma once
#include <cstring>

#include "raster/blend8.h"
#include "raster/color_reduction.h"
#include "raster/draw_record.h"
#include "raster/fragment_ops.h"
#include "raster/framebuffer.h"
#include "raster/quad_vector.h"

namespace pineda::raster::quad_ops {

// Bit position of each RGBA channel in a pixel as a little-endian uint32.
struct ChannelShift {
  uint32_t at[4];
};
constexpr ChannelShift kRgbaShift{{0, 8, 16, 24}};
constexpr ChannelShift kBgraShift{{16, 8, 0, 24}};

struct QuadColor {
  F4 c[4];  // r, g, b, a; one lane per pixel
};

inline uint8_t* color_address(const Framebuffer& fb, int x, int y) {
  return fb.color.base + static_cast<ptrdiff_t>(y) * fb.color.stride + static_cast<ptrdiff_t>(x) * 4;
}

// One blend factor for channel `c` of the four pixels.
inline F4 blend_factors(BlendFactor f, int c, const QuadColor& src, const QuadColor& dst, const float k[4]) {
  const F4 one = splat(1.f);
  switch (f) {
    case BlendFactor::Zero: return splat(0.f);
    case BlendFactor::One: return one;
    case BlendFactor::SrcColor: return src.c[c];
    case BlendFactor::OneMinusSrcColor: return one - src.c[c];
    case BlendFactor::DstColor: return dst.c[c];
    case BlendFactor::OneMinusDstColor: return one - dst.c[c];
    case BlendFactor::SrcAlpha: return src.c[3];
    case BlendFactor::OneMinusSrcAlpha: return one - src.c[3];
    case BlendFactor::DstAlpha: return dst.c[3];
    case BlendFactor::OneMinusDstAlpha: return one - dst.c[3];
    case BlendFactor::ConstantColor: return splat(k[c]);
    case BlendFactor::OneMinusConstantColor: return splat(1.f - k[c]);
    case BlendFactor::ConstantAlpha: return splat(k[3]);
    case BlendFactor::OneMinusConstantAlpha: return splat(1.f - k[3]);
    case BlendFactor::SrcAlphaSaturate: {
      if (c == 3) return one;
      const F4 a = src.c[3], b = one - dst.c[3];
      return a < b ? a : b;
    }
  }
  return one;
}

inline QuadColor blend_quad(const DrawRecord& d, const QuadColor& src, const QuadColor& dst) {
  const BlendState& b = d.state.blend_state;
  QuadColor out;
  for (int c = 0; c < 4; ++c) {
    const bool alpha = c == 3;
    const BlendEquation eq = alpha ? b.eq_alpha : b.eq_rgb;
    const F4 s = src.c[c], t = dst.c[c];
    if (eq == BlendEquation::Min) {
      out.c[c] = s < t ? s : t;
      continue;
    }
    if (eq == BlendEquation::Max) {
      out.c[c] = s > t ? s : t;
      continue;
    }
    const F4 ss = s * blend_factors(alpha ? b.src_alpha : b.src_rgb, c, src, dst, d.blend_color);
    const F4 tt = t * blend_factors(alpha ? b.dst_alpha : b.dst_rgb, c, src, dst, d.blend_color);
    out.c[c] = eq == BlendEquation::Add ? ss + tt : (eq == BlendEquation::Subtract ? ss - tt : tt - ss);
  }
  return out;
}

// The pixel centres of the first quad of a row of quads at (x, y), relative to the primitive's
// reference point (exact while the primitive stays near the framebuffer); quad q's x offsets
// are those plus 2q.
inline F4 quad_row_ox0(const PrimSetup& p, int x) { return splat(static_cast<float>(x) + 0.5f - p.ref_x) + F4{0.f, 1.f, 0.f, 1.f}; }
inline F4 quad_row_oy(const PrimSetup& p, int y) { return splat(static_cast<float>(y) + 0.5f - p.ref_y) + F4{0.f, 0.f, 1.f, 1.f}; }

// A quad's two rows of two 32-bit values (colour or depth) in and out of a register as 8-byte
// halves: a 16-byte load of a local array filled by 8-byte copies misses store forwarding (a
// quarter of copy_blur's blending routine waited there).
typedef uint64_t QuadRows __attribute__((vector_size(16)));
inline U4 load_quad_rows(const void* row0, const void* row1) {
  uint64_t top, bottom;
  std::memcpy(&top, row0, 8);
  std::memcpy(&bottom, row1, 8);
  return reinterpret_cast<U4>(QuadRows{top, bottom});
}
inline void store_quad_rows(void* row0, void* row1, U4 v) {
  const QuadRows rows = reinterpret_cast<QuadRows>(v);
  const uint64_t top = rows[0], bottom = rows[1];
  std::memcpy(row0, &top, 8);
  std::memcpy(row1, &bottom, 8);
}

// The quad's pixels, put together in registers (as load_quad_rows).
inline U4 load_pixels(uint8_t* const px[4], unsigned mask) {
  if (mask == 0xf) return load_quad_rows(px[0], px[2]);
  auto pixel = [&](int i) {
    uint32_t v = 0;
    if (px[i]) std::memcpy(&v, px[i], 4);
    return v;
  };
  return U4{pixel(0), pixel(1), pixel(2), pixel(3)};
}

// The destination pixels blending and logic op read, as the target's format holds them: a
// texture level made without data keeps bytes its format has not (an RGB level's alpha reads 1).
inline U4 load_destination(const Framebuffer& fb, uint8_t* const px[4], unsigned mask) {
  U4 old = load_pixels(px, mask);
  if (fb.color.reduction.active)
    for (int i = 0; i < 4; ++i) old[i] = reduce_pixel(fb.color.reduction, old[i]);
  return old;
}

template <bool kBlend, bool kOver>
[[gnu::always_inline]] inline void write_quad(const DrawRecord& d, const Framebuffer& fb, int x, int y, unsigned mask, const QuadColor& col) {
  const DrawState& s = d.state;
  const ChannelShift& shift = fb.color.format == ColorFormat::BGRA8 ? kBgraShift : kRgbaShift;
  uint8_t* const row0 = color_address(fb, x, y);
  uint8_t* const row1 = (mask & 0xc) ? color_address(fb, x, y + 1) : nullptr;
  uint8_t* const px[4] = {(mask & 1) ? row0 : nullptr, (mask & 2) ? row0 + 4 : nullptr, (mask & 4) ? row1 : nullptr,
                          (mask & 8) ? row1 + 4 : nullptr};
  U4 packed = {0, 0, 0, 0};
  if constexpr (kBlend && kOver) {
    for (int c = 0; c < 4; ++c) packed |= to_unorm8(col.c[c]) << shift.at[c];
    packed = blend_over8(packed, load_destination(fb, px, mask));
  } else if constexpr (kBlend) {
    const U4 old = load_destination(fb, px, mask);
    if (s.logic_op_enabled) {
      for (int c = 0; c < 4; ++c) {
        const U4 src = to_unorm8(col.c[c]), dst = (old >> shift.at[c]) & 0xffu;
        for (int i = 0; i < 4; ++i)
          packed[i] |= uint32_t{logic_op(s.logic_op, static_cast<uint8_t>(src[i]), static_cast<uint8_t>(dst[i]))}
                       << shift.at[c];
      }
    } else {
      QuadColor dst;
      for (int c = 0; c < 4; ++c) dst.c[c] = from_unorm8(old >> shift.at[c]);
      // The source is converted to the buffer's precision first, as llvmpipe does for unorm8.
      QuadColor src;
      for (int c = 0; c < 4; ++c) src.c[c] = from_unorm8(to_unorm8(col.c[c]));
      const QuadColor out = blend_quad(d, src, dst);
      for (int c = 0; c < 4; ++c) packed |= to_unorm8(out.c[c]) << shift.at[c];
    }
  } else {
    for (int c = 0; c < 4; ++c) packed |= to_unorm8(col.c[c]) << shift.at[c];
  }
  if (fb.color.reduction.active)
    for (int i = 0; i < 4; ++i) packed[i] = reduce_pixel(fb.color.reduction, packed[i]);
  if (mask == 0xf && d.color_write_all) {
    uint32_t v[4] = {packed[0], packed[1], packed[2], packed[3]};
    std::memcpy(px[0], &v[0], 8);
    std::memcpy(px[2], &v[2], 8);
    return;
  }
  uint32_t keep = 0;  // bits of the old pixel the colour mask preserves
  for (int c = 0; c < 4; ++c)
    if (!s.color_write[c]) keep |= 0xffu << shift.at[c];
  for (int i = 0; i < 4; ++i) {
    if (!px[i]) continue;
    uint32_t v = packed[i];
    if (keep) {
      uint32_t old;
      std::memcpy(&old, px[i], 4);
      v = (v & ~keep) | (old & keep);
    }
    std::memcpy(px[i], &v, 4);
  }
}

template <bool kDepth, bool kStencil>
unsigned depth_stencil(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, unsigned mask,
                       F4 ox, F4 oy) {
  const DrawState& s = d.state;
  const StencilFace& face = p.back_facing ? s.stencil_back : s.stencil_front;
  const uint8_t ref = d.stencil_ref[p.back_facing ? 1 : 0];
  for (int i = 0; i < 4; ++i) {
    if (!(mask & (1u << i))) continue;
    const int px = x + (i & 1), py = y + (i >> 1);
    uint8_t* stencil = nullptr;
    uint8_t sv = 0;
    auto update_stencil = [&](StencilOp op) {
      const uint8_t nv = stencil_op(op, sv, ref);
      *stencil = static_cast<uint8_t>((sv & ~face.write_mask) | (nv & face.write_mask));
    };
    if constexpr (kStencil) {
      stencil = fb.stencil.base + static_cast<ptrdiff_t>(py) * fb.stencil.stride + px;
      sv = *stencil;
      if (!compare(face.func, static_cast<uint8_t>(ref & face.value_mask), static_cast<uint8_t>(sv & face.value_mask))) {
        update_stencil(face.fail);
        mask &= ~(1u << i);
        continue;
      }
    }
    if constexpr (kDepth) {
      double z = p.z0 + p.dzdx * ox[i] + p.dzdy * oy[i];
      z = z > 0.0 ? (z < d.depth_max ? z : d.depth_max) : 0.0;
      const uint32_t zi = static_cast<uint32_t>(z + 0.5);
      uint32_t* depth = fb.depth.base + static_cast<ptrdiff_t>(py) * fb.depth.stride + px;
      if (!compare(s.depth_func, zi, *depth)) {
        if constexpr (kStencil) update_stencil(face.depth_fail);
        mask &= ~(1u << i);
        continue;
      }
      if (s.depth_write) *depth = zi;
    }
    if constexpr (kStencil) update_stencil(face.depth_pass);
  }
  return mask;
}

using D4 = double __attribute__((vector_size(32)));

// The quad's depth values: the same double expression per lane as the stencil path.
[[gnu::always_inline]] inline U4 quad_depth(const DrawRecord& d, const PrimSetup& p, F4 ox, F4 oy) {
  const D4 dx = __builtin_convertvector(ox, D4), dy = __builtin_convertvector(oy, D4);
  D4 z = p.z0 + p.dzdx * dx + p.dzdy * dy;
  const D4 zero = {0.0, 0.0, 0.0, 0.0};
  const D4 max = zero + d.depth_max;
  z = z > zero ? (z < max ? z : max) : zero;
  z += 0.5;
  // Below 2^31 the signed conversion truncates exactly as the unsigned one does.
  if (d.depth_max < 2147483647.0) return reinterpret_cast<U4>(__builtin_convertvector(z, I4));
  return U4{static_cast<uint32_t>(z[0]), static_cast<uint32_t>(z[1]), static_cast<uint32_t>(z[2]),
            static_cast<uint32_t>(z[3])};
}

inline unsigned lane_mask(I4 v) {
#if defined(__SSE2__)
  return static_cast<unsigned>(_mm_movemask_ps(reinterpret_cast<__m128>(v)));
#else
  return (v[0] ? 1u : 0u) | (v[1] ? 2u : 0u) | (v[2] ? 4u : 0u) | (v[3] ? 8u : 0u);
#endif
}

inline unsigned depth_pass(CompareFunc f, U4 z, U4 stored) {
  switch (f) {
    case CompareFunc::Never: return 0;
    case CompareFunc::Less: return lane_mask(z < stored);
    case CompareFunc::Equal: return lane_mask(z == stored);
    case CompareFunc::LessEqual: return lane_mask(z <= stored);
    case CompareFunc::Greater: return lane_mask(z > stored);
    case CompareFunc::NotEqual: return lane_mask(z != stored);
    case CompareFunc::GreaterEqual: return lane_mask(z >= stored);
    case CompareFunc::Always: return 0xf;
  }
  return 0xf;
}

// Depth test and write without stencil: the four lanes at once.
[[gnu::always_inline]] inline unsigned depth_only(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, unsigned mask,
                    F4 ox, F4 oy) {
  uint32_t* const row0 = fb.depth.base + static_cast<ptrdiff_t>(y) * fb.depth.stride + x;
  const U4 zi = quad_depth(d, p, ox, oy);
  // A partly covered quad inside the buffer too, without a branch per pixel: its other pixels
  // are written back as they were (a quad lies in one tile, which one thread owns).
  if (mask == 0xf || (x + 1 < fb.width && y + 1 < fb.height)) {
    uint32_t* const row1 = row0 + fb.depth.stride;
    const U4 stored = load_quad_rows(row0, row1);
    const unsigned pass = depth_pass(d.state.depth_func, zi, stored) & mask;
    if (pass && d.state.depth_write) {
      const I4 passed = (I4{1, 2, 4, 8} & static_cast<int>(pass)) != 0;
      store_quad_rows(row0, row1, passed ? zi : stored);
    }
    return pass;
  }
  uint32_t* row[2] = {row0, nullptr};
  if (mask & 0xc) row[1] = row0 + fb.depth.stride;
  U4 stored = {0, 0, 0, 0};
  for (int i = 0; i < 4; ++i)
    if (mask & (1u << i)) stored[i] = row[i >> 1][i & 1];
  mask &= depth_pass(d.state.depth_func, zi, stored);
  if (d.state.depth_write)
    for (int i = 0; i < 4; ++i)
      if (mask & (1u << i)) row[i >> 1][i & 1] = zi[i];
  return mask;
}


}  // namespace pineda::raster::quad_ops
