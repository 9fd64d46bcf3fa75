#include "raster/reference_fragment.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "raster/color_reduction.h"
#include "raster/fragment_ops.h"
#include "raster/sampler.h"
#include "raster/tex_env.h"

namespace pineda::raster {
namespace {

double clamp_unit(double v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; }

// Nearest unorm8, ties to even, from a double.
uint8_t unorm8(double v) { return static_cast<uint8_t>(std::nearbyint(clamp_unit(v) * 255.0)); }

// Byte position of each RGBA channel in a pixel.
void channel_offsets(ColorFormat format, int out[4]) {
  const bool bgra = format == ColorFormat::BGRA8;
  out[0] = bgra ? 2 : 0;
  out[1] = 1;
  out[2] = bgra ? 0 : 2;
  out[3] = 3;
}

// GL 1.5 sections 3.9 and 3.10, in double: the secondary colour added, then fog blended in.
void color_sum_and_fog(const DrawRecord& d, const ReferenceQuad& q, int i, double color[4]) {
  if (d.secondary_plane >= 0)
    for (int c = 0; c < 3; ++c) color[c] = clamp_unit(color[c] + clamp_unit(q.attr[d.secondary_plane + c][i]));
  if (d.fog_plane < 0) return;
  const Fog& fog = d.state.fog;
  const double z = q.attr[d.fog_plane][i];
  double f = 1.0;
  switch (fog.mode) {
    case FogMode::Linear: f = fog.end != fog.start ? (fog.end - z) / (double{fog.end} - fog.start) : 0.0; break;
    case FogMode::Exp: f = std::exp(-double{fog.density} * z); break;
    case FogMode::Exp2: f = std::exp(-(fog.density * z) * (fog.density * z)); break;
  }
  f = clamp_unit(f);
  for (int c = 0; c < 3; ++c) color[c] = f * color[c] + (1.0 - f) * fog.color[c];
}

// The fragment colours of the quad after interpolation (or flat shading) and texturing.
void quad_colors(const DrawRecord& d, const float flat_color[4], const ReferenceQuad& q, double out[4][4]) {
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 4; ++c) out[i][c] = d.state.flat_shading ? flat_color[c] : clamp_unit(q.attr[c][i]);
  for (int k = 0; k < d.num_units; ++k) {
    const TextureUnit& unit = d.state.texture_units[d.units[k]];
    const int base = d.tex_plane[k], r_plane = d.r_plane[k];
    float s[4], t[4], r[4] = {0, 0, 0, 0}, texel[4][4];
    for (int i = 0; i < 4; ++i) {
      s[i] = static_cast<float>(q.attr[base][i] / q.attr[base + 2][i]);
      t[i] = static_cast<float>(q.attr[base + 1][i] / q.attr[base + 2][i]);
      if (r_plane >= 0) r[i] = static_cast<float>(q.attr[r_plane][i] / q.attr[base + 2][i]);
    }
    sample_quad(*unit.image, unit.sampler, s, t, r, texel);
    for (int i = 0; i < 4; ++i) {
      float frag[4];
      for (int c = 0; c < 4; ++c) frag[c] = static_cast<float>(out[i][c]);
      apply_tex_env(unit.env_mode, unit.image->texenv_format(), unit.env_color, texel[i], frag);
      for (int c = 0; c < 4; ++c) out[i][c] = frag[c];
    }
  }
  for (int i = 0; i < 4; ++i) {
    color_sum_and_fog(d, q, i, out[i]);
    out[i][3] *= q.coverage[i];  // GL 1.5 section 3.12
  }
}

// Stencil and depth for one pixel; false when the fragment is discarded.
bool depth_stencil(const DrawRecord& d, bool back_facing, const Framebuffer& fb, int px, int py, double z) {
  const DrawState& s = d.state;
  const bool stencil_on = s.stencil_test && fb.stencil.base && fb.stencil.bits > 0;
  const bool depth_on = s.depth_test && fb.depth.base && fb.depth.bits > 0;
  const StencilFace& face = back_facing ? s.stencil_back : s.stencil_front;
  const uint8_t ref = d.stencil_ref[back_facing ? 1 : 0];
  uint8_t* stencil = stencil_on ? fb.stencil.base + static_cast<ptrdiff_t>(py) * fb.stencil.stride + px : nullptr;
  auto update_stencil = [&](StencilOp op) {
    if (!stencil) return;
    const uint8_t old = *stencil;
    const uint8_t nv = stencil_op(op, old, ref);
    *stencil = static_cast<uint8_t>((old & ~face.write_mask) | (nv & face.write_mask));
  };
  if (stencil && !compare(face.func, static_cast<uint8_t>(ref & face.value_mask),
                          static_cast<uint8_t>(*stencil & face.value_mask))) {
    update_stencil(face.fail);
    return false;
  }
  if (depth_on) {
    const double clamped = std::clamp(z, 0.0, d.depth_max);
    const uint32_t zi = static_cast<uint32_t>(std::floor(clamped + 0.5));
    uint32_t* depth = fb.depth.base + static_cast<ptrdiff_t>(py) * fb.depth.stride + px;
    if (!compare(s.depth_func, zi, *depth)) {
      update_stencil(face.depth_fail);
      return false;
    }
    if (s.depth_write) *depth = zi;
  }
  update_stencil(face.depth_pass);
  return true;
}

void write_color(const DrawRecord& d, const Framebuffer& fb, int px, int py, const double color[4]) {
  const DrawState& s = d.state;
  uint8_t* pixel = fb.color.base + static_cast<ptrdiff_t>(py) * fb.color.stride + static_cast<ptrdiff_t>(px) * 4;
  int at[4];
  channel_offsets(fb.color.format, at);
  uint8_t out[4];
  if (s.logic_op_enabled) {
    for (int c = 0; c < 4; ++c) out[c] = logic_op(s.logic_op, unorm8(color[c]), pixel[at[c]]);
  } else if (s.blend) {
    float src[4], dst[4];
    for (int c = 0; c < 4; ++c) {
      src[c] = static_cast<float>(color[c]);
      dst[c] = pixel[at[c]] / 255.f;
    }
    const BlendState& b = s.blend_state;
    for (int c = 0; c < 4; ++c) {
      const bool alpha = c == 3;
      const double sf = blend_factor(alpha ? b.src_alpha : b.src_rgb, c, src, dst, d.blend_color);
      const double df = blend_factor(alpha ? b.dst_alpha : b.dst_rgb, c, src, dst, d.blend_color);
      const double sv = color[c], dv = pixel[at[c]] / 255.0;
      double v = 0.0;
      switch (alpha ? b.eq_alpha : b.eq_rgb) {
        case BlendEquation::Add: v = sv * sf + dv * df; break;
        case BlendEquation::Subtract: v = sv * sf - dv * df; break;
        case BlendEquation::ReverseSubtract: v = dv * df - sv * sf; break;
        case BlendEquation::Min: v = std::min(sv, dv); break;
        case BlendEquation::Max: v = std::max(sv, dv); break;
      }
      out[c] = unorm8(v);
    }
  } else {
    for (int c = 0; c < 4; ++c) out[c] = unorm8(color[c]);
  }
  if (fb.color.reduction.active) reduce_bytes(fb.color.reduction, out);
  for (int c = 0; c < 4; ++c)
    if (s.color_write[c]) pixel[at[c]] = out[c];
}

}  // namespace

uint32_t reference_shade_quad(const DrawRecord& d, bool back_facing, const float flat_color[4], const Framebuffer& fb,
                              const ReferenceQuad& quad) {
  double color[4][4];
  quad_colors(d, flat_color, quad, color);
  uint32_t passed = 0;
  for (int i = 0; i < 4; ++i) {
    if (!(quad.mask & (1u << i))) continue;
    const int px = quad.x + (i & 1), py = quad.y + (i >> 1);
    if (d.state.alpha_test && !alpha_passes(d, static_cast<float>(color[i][3]))) continue;
    if (!depth_stencil(d, back_facing, fb, px, py, quad.z[i])) continue;
    ++passed;
    if (fb.color.base && d.color_write_any) write_color(d, fb, px, py, color[i]);
  }
  return passed;
}

}  // namespace pineda::raster
