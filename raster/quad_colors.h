// The fixed-function colour of a 2x2 quad at its pixel centres: interpolated colour, texture
// environments, colour sum and fog. Shared by the single-sampled routines
// (fragment_pipeline.cpp) and the multisampled ones that shade once per pixel (sample_quads.cpp).
#pragma once

#include "raster/draw_record.h"
#include "raster/fragment_extras.h"
#include "raster/quad_ops.h"
#include "raster/quad_vector.h"
#include "raster/sampler.h"
#include "raster/tex_env.h"

namespace pineda::raster::quad_ops {

inline F4 eval(const Plane& p, F4 ox, F4 oy) { return p.a0 + p.dx * ox + p.dy * oy; }

// Interpolated fragment colours of the quad, textured (then summed and fogged: kExtras).
template <bool kTex, bool kFlat, bool kExtras>
[[gnu::always_inline]] inline QuadColor quad_colors(const DrawRecord& d, const PrimSetup& p, F4 ox, F4 oy) {
  QuadColor col;
  if constexpr (kFlat) {
    for (int c = 0; c < 4; ++c) col.c[c] = splat(p.flat_color[c]);
  } else if (p.perspective) {
    const F4 w = 1.f / eval(p.inv_w, ox, oy);
    for (int c = 0; c < 4; ++c) col.c[c] = clamp01(eval(p.planes[c], ox, oy) * w);
  } else {
    for (int c = 0; c < 4; ++c) col.c[c] = clamp01(eval(p.planes[c], ox, oy));
  }

  if constexpr (kTex) {
    if (d.texture_in_lanes) {
      const TextureUnit& unit = d.state.texture_units[d.units[0]];
      const Plane* tp = &p.planes[d.tex_plane[0]];
      const F4 q = eval(tp[2], ox, oy);
      F4 texel[4];
      d.fast_sampler[0](*unit.image, unit.sampler, eval(tp[0], ox, oy) / q, eval(tp[1], ox, oy) / q, texel);
      for (int c = 0; c < d.modulated_channels; ++c) col.c[c] = d.replaces_in_lanes ? texel[c] : col.c[c] * texel[c];
      if constexpr (kExtras) apply_color_sum_and_fog(d, p, ox, oy, col.c);
      return col;
    }
    // Every unit is sampled before any environment runs: COMBINE may read any unit's texel.
    float texel[kMaxTextureUnits][4][4];  // [unit][pixel][channel]
    for (int k = 0; k < d.num_units; ++k) {
      const TextureUnit& unit = d.state.texture_units[d.units[k]];
      const Plane* tp = &p.planes[d.tex_plane[k]];
      // (s/w) / (q/w) = s/q: 1/w cancels, so perspective needs no extra divide here.
      const F4 q = eval(tp[2], ox, oy);
      if (d.fast_sampler[k]) {
        F4 lanes[4];
        d.fast_sampler[k](*unit.image, unit.sampler, eval(tp[0], ox, oy) / q, eval(tp[1], ox, oy) / q, lanes);
        for (int i = 0; i < 4; ++i)
          for (int c = 0; c < 4; ++c) texel[d.units[k]][i][c] = lanes[c][i];
        continue;
      }
      float s[4], t[4], r[4];
      store4(s, eval(tp[0], ox, oy) / q);
      store4(t, eval(tp[1], ox, oy) / q);
      if (d.r_plane[k] < 0) {
        sample_quad(*unit.image, unit.sampler, s, t, texel[d.units[k]]);
        continue;
      }
      store4(r, eval(p.planes[d.r_plane[k]], ox, oy) / q);
      sample_quad(*unit.image, unit.sampler, s, t, r, texel[d.units[k]]);
    }
    for (int i = 0; i < 4; ++i) {
      PixelTexels texels;
      for (int k = 0; k < d.num_units; ++k) texels.unit[d.units[k]] = texel[d.units[k]][i];
      const float primary[4] = {col.c[0][i], col.c[1][i], col.c[2][i], col.c[3][i]};
      float frag[4] = {primary[0], primary[1], primary[2], primary[3]};
      for (int k = 0; k < d.num_units; ++k)
        apply_unit_env(d.state.texture_units[d.units[k]], d.units[k], texels, primary, frag);
      for (int c = 0; c < 4; ++c) col.c[c][i] = frag[c];
    }
  }
  if constexpr (kExtras) apply_color_sum_and_fog(d, p, ox, oy, col.c);
  return col;
}

}  // namespace pineda::raster::quad_ops
