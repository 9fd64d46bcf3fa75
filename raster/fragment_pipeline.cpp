#include "raster/fragment_pipeline.h"

#include <array>
#include <cstring>
#include <utility>

#include "raster/fragment_ops.h"
#include "raster/sampler.h"
#include "raster/tex_env.h"

namespace pineda::raster {
namespace {

// Byte position of each RGBA channel in a pixel of the colour buffer.
struct ChannelOrder {
  int at[4];
};
constexpr ChannelOrder kRgbaOrder{{0, 1, 2, 3}};
constexpr ChannelOrder kBgraOrder{{2, 1, 0, 3}};

inline float eval(const Plane& p, float ox, float oy) { return p.a0 + p.dx * ox + p.dy * oy; }

// The quad's values are kept channel-major, c[channel][pixel], so that the loops over the four
// pixels vectorize.
using QuadColor = float[4][4];

// Interpolated fragment colours of the quad, textured.
template <bool kTex, bool kFlat>
void quad_colors(const DrawRecord& d, const PrimSetup& p, const float ox[4], const float oy[4], QuadColor col) {
  if constexpr (kFlat) {
    for (int c = 0; c < 4; ++c)
      for (int i = 0; i < 4; ++i) col[c][i] = p.flat_color[c];
  } else if (p.perspective) {
    float w[4];
    for (int i = 0; i < 4; ++i) w[i] = 1.f / eval(p.inv_w, ox[i], oy[i]);
    for (int c = 0; c < 4; ++c)
      for (int i = 0; i < 4; ++i) col[c][i] = eval(p.planes[c], ox[i], oy[i]) * w[i];
  } else {
    for (int c = 0; c < 4; ++c)
      for (int i = 0; i < 4; ++i) col[c][i] = eval(p.planes[c], ox[i], oy[i]);
  }
  for (int c = 0; c < 4; ++c)
    for (int i = 0; i < 4; ++i) col[c][i] = clamp01(col[c][i]);

  if constexpr (kTex) {
    for (int k = 0; k < d.num_units; ++k) {
      const TextureUnit& unit = d.state.texture_units[d.units[k]];
      const Plane* tp = &p.planes[kColorPlanes + kTexPlanesPerUnit * k];
      float s[4], t[4];
      for (int i = 0; i < 4; ++i) {
        // (s/w) / (q/w) = s/q: 1/w cancels, so perspective needs no extra divide here.
        const float q = eval(tp[2], ox[i], oy[i]);
        s[i] = eval(tp[0], ox[i], oy[i]) / q;
        t[i] = eval(tp[1], ox[i], oy[i]) / q;
      }
      float texel[4][4];
      sample_quad(*unit.image, unit.sampler, s, t, texel);
      for (int i = 0; i < 4; ++i) {
        float frag[4] = {col[0][i], col[1][i], col[2][i], col[3][i]};
        apply_tex_env(unit.env_mode, unit.image->base_format, unit.env_color, texel[i], frag);
        for (int c = 0; c < 4; ++c) col[c][i] = frag[c];
      }
    }
  }
}

uint8_t* color_address(const Framebuffer& fb, int x, int y) {
  return fb.color.base + static_cast<ptrdiff_t>(y) * fb.color.stride + static_cast<ptrdiff_t>(x) * 4;
}

// One blend factor for channel `c` of the four pixels.
void blend_factors(BlendFactor f, int c, const QuadColor src, const QuadColor dst, const float k[4], float out[4]) {
  switch (f) {
    case BlendFactor::SrcAlphaSaturate:
      for (int i = 0; i < 4; ++i) out[i] = c == 3 ? 1.f : std::min(src[3][i], 1.f - dst[3][i]);
      return;
    case BlendFactor::SrcColor:
    case BlendFactor::OneMinusSrcColor:
    case BlendFactor::SrcAlpha:
    case BlendFactor::OneMinusSrcAlpha:
    case BlendFactor::DstColor:
    case BlendFactor::OneMinusDstColor:
    case BlendFactor::DstAlpha:
    case BlendFactor::OneMinusDstAlpha: {
      const bool from_src = f == BlendFactor::SrcColor || f == BlendFactor::OneMinusSrcColor ||
                            f == BlendFactor::SrcAlpha || f == BlendFactor::OneMinusSrcAlpha;
      const bool alpha = f == BlendFactor::SrcAlpha || f == BlendFactor::OneMinusSrcAlpha ||
                         f == BlendFactor::DstAlpha || f == BlendFactor::OneMinusDstAlpha;
      const bool inverted = f == BlendFactor::OneMinusSrcColor || f == BlendFactor::OneMinusSrcAlpha ||
                            f == BlendFactor::OneMinusDstColor || f == BlendFactor::OneMinusDstAlpha;
      const float* v = (from_src ? src : dst)[alpha ? 3 : c];
      for (int i = 0; i < 4; ++i) out[i] = inverted ? 1.f - v[i] : v[i];
      return;
    }
    default: {
      const float constant = blend_factor(f, c, k, k, k);  // Zero, One and the constant colour
      for (int i = 0; i < 4; ++i) out[i] = constant;
      return;
    }
  }
}

void blend_quad(const DrawRecord& d, const QuadColor src, const QuadColor dst, QuadColor out) {
  const BlendState& b = d.state.blend_state;
  for (int c = 0; c < 4; ++c) {
    const bool alpha = c == 3;
    const BlendEquation eq = alpha ? b.eq_alpha : b.eq_rgb;
    if (eq == BlendEquation::Min || eq == BlendEquation::Max) {
      for (int i = 0; i < 4; ++i) out[c][i] = blend_equation(eq, src[c][i], 0.f, dst[c][i], 0.f);
      continue;
    }
    float sf[4], df[4];
    blend_factors(alpha ? b.src_alpha : b.src_rgb, c, src, dst, d.blend_color, sf);
    blend_factors(alpha ? b.dst_alpha : b.dst_rgb, c, src, dst, d.blend_color, df);
    for (int i = 0; i < 4; ++i) {
      const float s = src[c][i] * sf[i], t = dst[c][i] * df[i];
      out[c][i] = eq == BlendEquation::Add ? s + t : (eq == BlendEquation::Subtract ? s - t : t - s);
    }
  }
}

template <bool kBlend>
void write_quad(const DrawRecord& d, const Framebuffer& fb, int x, int y, unsigned mask, const QuadColor col) {
  const DrawState& s = d.state;
  const ChannelOrder& order = fb.color.format == ColorFormat::BGRA8 ? kBgraOrder : kRgbaOrder;
  uint8_t* px[4] = {};
  for (int i = 0; i < 4; ++i)
    if (mask & (1u << i)) px[i] = color_address(fb, x + (i & 1), y + (i >> 1));
  uint8_t bytes[4][4];  // [pixel][byte in memory order]
  if constexpr (kBlend) {
    uint8_t dst_bytes[4][4] = {};
    for (int i = 0; i < 4; ++i)
      if (px[i]) std::memcpy(dst_bytes[i], px[i], 4);
    if (s.logic_op_enabled) {
      for (int c = 0; c < 4; ++c)
        for (int i = 0; i < 4; ++i)
          bytes[i][order.at[c]] = logic_op(s.logic_op, to_unorm8(col[c][i]), dst_bytes[i][order.at[c]]);
    } else {
      QuadColor dst, out;
      for (int c = 0; c < 4; ++c)
        for (int i = 0; i < 4; ++i) dst[c][i] = static_cast<float>(dst_bytes[i][order.at[c]]) * (1.f / 255.f);
      blend_quad(d, col, dst, out);
      for (int c = 0; c < 4; ++c)
        for (int i = 0; i < 4; ++i) bytes[i][order.at[c]] = to_unorm8(out[c][i]);
    }
  } else {
    for (int c = 0; c < 4; ++c)
      for (int i = 0; i < 4; ++i) bytes[i][order.at[c]] = to_unorm8(col[c][i]);
  }
  if (d.color_write_all) {
    for (int i = 0; i < 4; ++i)
      if (px[i]) std::memcpy(px[i], bytes[i], 4);
    return;
  }
  for (int i = 0; i < 4; ++i)
    if (px[i])
      for (int c = 0; c < 4; ++c)
        if (s.color_write[c]) px[i][order.at[c]] = bytes[i][order.at[c]];
}

template <bool kTex, bool kDepth, bool kStencil, bool kBlend, bool kFlat>
void shade_quad(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, unsigned mask) {
  const DrawState& s = d.state;
  float ox[4], oy[4];
  for (int i = 0; i < 4; ++i) {
    ox[i] = static_cast<float>(x + (i & 1)) + 0.5f - p.ref_x;
    oy[i] = static_cast<float>(y + (i >> 1)) + 0.5f - p.ref_y;
  }
  QuadColor col;
  quad_colors<kTex, kFlat>(d, p, ox, oy, col);

  if (s.alpha_test) {
    for (int i = 0; i < 4; ++i)
      if (!compare(s.alpha_func, col[3][i], d.alpha_ref)) mask &= ~(1u << i);
  }

  if constexpr (kDepth || kStencil) {
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
  }

  if (!mask || !fb.color.base || !d.color_write_any) return;
  write_quad<kBlend>(d, fb, x, y, mask, col);
}

template <int kBits>
constexpr QuadRoutine routine_for() {
  return &shade_quad<(kBits & 1) != 0, (kBits & 2) != 0, (kBits & 4) != 0, (kBits & 8) != 0, (kBits & 16) != 0>;
}

template <int... kBits>
constexpr auto make_table(std::integer_sequence<int, kBits...>) {
  return std::array<QuadRoutine, sizeof...(kBits)>{routine_for<kBits>()...};
}

constexpr auto kRoutines = make_table(std::make_integer_sequence<int, 32>{});

}  // namespace

QuadRoutine select_quad_routine(const FragmentKey& key) {
  const int bits = (key.textured ? 1 : 0) | (key.depth ? 2 : 0) | (key.stencil ? 4 : 0) | (key.blend ? 8 : 0) |
                   (key.flat ? 16 : 0);
  return kRoutines[bits];
}

}  // namespace pineda::raster
