// The fixed-function stages a draw may add around texturing, for the routines whose key has
// `extras`: line and polygon stipple (fragments never generated), the colour sum, fog and the
// coverage of antialiased points and lines (GL 1.5 sections 3.4.2, 3.5.2, 3.9, 3.10 and 3.12).
#pragma once
#include <cmath>

#include "raster/draw_record.h"
#include "raster/quad_vector.h"
#include "raster/smooth_coverage.h"

namespace pineda::raster {

// Bit i: pixel i of the quad at (x, y) (x and y even) survives the stipple patterns.
inline unsigned stipple_mask(const DrawRecord& d, const PrimSetup& p, int x, int y) {
  const DrawState& s = d.state;
  if (p.kind == CoverageKind::Triangle && s.polygon_stipple.enabled) {
    const int bit = x & 31;  // even, so the quad's two columns share a row word
    const uint32_t r0 = s.polygon_stipple.rows[y & 31] >> bit, r1 = s.polygon_stipple.rows[(y + 1) & 31] >> bit;
    return (r0 & 3u) | ((r1 & 3u) << 2);
  }
  if (p.kind == CoverageKind::Line && s.line_stipple.enabled) {
    const LineCoverage& l = p.line;
    unsigned mask = 0;
    const float last = std::ceil(l.stipple_length) - 1.f;  // the last whole step of the segment
    for (int i = 0; i < 4; ++i) {
      const int major = l.x_major ? x + (i & 1) : y + (i >> 1);
      const float d = std::floor((static_cast<float>(major) + 0.5f - l.stipple_origin) * static_cast<float>(l.stipple_step));
      const float step = d < 0.f ? 0.f : (d > last ? last : d);
      const int64_t n = static_cast<int64_t>(l.stipple_count + step);
      const int64_t b = (n / s.line_stipple.factor) & 15;
      if ((s.line_stipple.pattern >> b) & 1u) mask |= 1u << i;
    }
    return mask;
  }
  return 0xf;
}

inline F4 eval_plane(const Plane& p, F4 ox, F4 oy) { return p.a0 + p.dx * ox + p.dy * oy; }

// Interpolated value of plane k (perspective-correct when the primitive is).
inline F4 varying(const PrimSetup& p, int k, F4 ox, F4 oy) {
  const F4 v = eval_plane(p.planes[k], ox, oy);
  return p.perspective ? v / eval_plane(p.inv_w, ox, oy) : v;
}

// The colour sum and fog on the quad's colours c[0..3] (r, g, b, a, one lane per pixel).
inline void apply_color_sum_and_fog(const DrawRecord& d, const PrimSetup& p, F4 ox, F4 oy, F4 (&c)[4]) {
  if (d.secondary_plane >= 0)
    for (int k = 0; k < 3; ++k) c[k] = clamp01(c[k] + clamp01(varying(p, d.secondary_plane + k, ox, oy)));
  if (d.fog_plane < 0) return;
  const Fog& fog = d.state.fog;
  const F4 z = varying(p, d.fog_plane, ox, oy);
  F4 f = splat(1.f);  // (every mode sets it; GCC cannot tell)
  switch (fog.mode) {
    case FogMode::Linear: {
      const float range = fog.end - fog.start;
      // GL leaves start == end undefined; Mesa's 1/(end-start) becomes 0 scale there.
      const float scale = range != 0.f ? 1.f / range : 0.f;
      f = (splat(fog.end) - z) * scale;
      break;
    }
    case FogMode::Exp:
      for (int i = 0; i < 4; ++i) f[i] = std::exp(-fog.density * z[i]);
      break;
    case FogMode::Exp2:
      for (int i = 0; i < 4; ++i) {
        const float dz = fog.density * z[i];
        f[i] = std::exp(-dz * dz);
      }
      break;
  }
  f = clamp01(f);
  for (int k = 0; k < 3; ++k) c[k] = f * c[k] + (splat(1.f) - f) * fog.color[k];
}

// GL 1.5 section 3.12: the coverage of an antialiased primitive, and a multisampled point's
// fade (section 3.3), multiply the fragment's alpha, after fog. `alpha` holds the quad at (x, y);
// only the pixels of `mask` are worked out (the others will not be written).
inline void apply_coverage(const PrimSetup& p, int x, int y, unsigned mask, F4& alpha) {
  if (p.sample_point.fade != 1.f) alpha *= p.sample_point.fade;
  if (!(p.smooth.size > 0.0)) return;
  float coverage[4];
  smooth_quad_coverage(p, x, y, mask, coverage);
  alpha *= load4(coverage);
}

}  // namespace pineda::raster
