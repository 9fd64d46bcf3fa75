// Bilinear sampling of RGBA8 Planar images for the four pixels of a quad at once, in integers
// with 8-bit fractions as llvmpipe's unorm8 path does: texel indices and weights per lane,
// texels gathered, weighted sums exact in 32 bits, one LOD per quad. Specialized per wrap mode
// pair; selected once per draw for the keys it covers, the float sampler (sampler.h) for the rest.
#pragma once

#include "raster/mip_selection.h"
#include "raster/quad_vector.h"
#include "raster/sampler.h"
#include "raster/simd_path.h"
#include "raster/texel_addressing.h"
#include "raster/texture.h"

namespace pineda::raster {

// out[c]: channel c (RGBA, as stored) of the four pixels, in [0, 1].
using QuadSampler = void (*)(const TextureImage& image, const Sampler& sampler, F4 s, F4 t, F4 out[4]);

// The specialized sampler for this image and sampler, or null when they need the general one:
// only colour Planar images (and Rect ones clamped to the edge) whose filters are linear within a level (LINEAR magnification;
// LINEAR, LINEAR_MIPMAP_NEAREST or LINEAR_MIPMAP_LINEAR minification) with REPEAT or
// CLAMP_TO_EDGE on s and t qualify.
QuadSampler select_bilinear8_sampler(const TextureImage& image, const Sampler& sampler,
                                     SimdPath path = SimdPath::Best);

// The level or pair of levels that sampler reads for the quad at (s, t). Inline: returned from
// a call, the choice was put together on the stack and read back at a size it was not written
// at, a store-forwarding stall that took most of the function's time (glmark2's terrain).
inline LevelChoice bilinear8_quad_levels(const TextureImage& image, const Sampler& sampler, F4 s, F4 t) {
  // Without mipmaps both magnification and minification filter level 0 bilinearly: the level
  // of detail changes nothing (choose_levels returns level 0 for any lambda).
  if (sampler.min_filter == TexFilter::Linear) return LevelChoice{};
  float sa[4], ta[4];
  for (int i = 0; i < 4; ++i) {
    sa[i] = sane(s[i]);
    ta[i] = sane(t[i]);
  }
  const int max_level = static_cast<int>(image.levels.size()) - 1;
  return choose_levels(sampler, quad_lambda(image.levels[0], sa, ta), max_level);
}

// The clamped lambdas (clamped_lambda) of a block's four quads at once, quad q in lane q (its
// pixels at s[4q..4q+3], t likewise; bias[q] its sampler's lod_bias plus any bias of its own):
// the operations of sane, quad_lambda, lambda_from_rho2 and clamped_lambda per lane, so
// levels_at(sampler, lambda[q], last level) is bilinear8_quad_levels' choice for a mipmapping
// minification filter. The four quads' dependent chains run side by side (one quad at a time,
// they were a tenth of glmark2 terrain's time).
inline F4 bilinear8_block_lambdas(const TextureImage& image, const Sampler& sampler, const float* s, const float* t,
                                  F4 bias) {
  const F4 zero = F4{};
  auto pixel = [&](const float* c, int i) { return sane4(F4{c[i], c[4 + i], c[8 + i], c[12 + i]}); };
  const F4 s0 = pixel(s, 0), s1 = pixel(s, 1), s2 = pixel(s, 2);
  const F4 t0 = pixel(t, 0), t1 = pixel(t, 1), t2 = pixel(t, 2);
  // quad_lambda
  const float w = static_cast<float>(image.levels[0].width), h = static_cast<float>(image.levels[0].height);
  const F4 dudx = (s1 - s0) * w, dvdx = (t1 - t0) * h;
  const F4 dudy = (s2 - s0) * w, dvdy = (t2 - t0) * h;
  const F4 across = dudx * dudx + dvdx * dvdx, down = dudy * dudy + dvdy * dvdy;
  const F4 rho2 = across < down ? down : across;  // std::max(across, down)
  // lambda_from_rho2
  const I4 positive = rho2 > zero;
  const I4 subnormal = positive & (rho2 < splat(0x1p-126f));
  U4 bits = reinterpret_cast<U4>(subnormal ? rho2 * 0x1p24f : rho2);
  const I4 infinite = reinterpret_cast<I4>(bits) >= 0x7f800000;  // (positive lanes: sign bit clear)
  const I4 e = reinterpret_cast<I4>(bits >> 23) - 126 - (subnormal & 24);
  bits = (bits & 0x807fffffu) | 0x3f000000u;
  const F4 m = reinterpret_cast<F4>(bits);
  F4 lambda = 0.5f * (__builtin_convertvector(e - 1, F4) + (2.f * m - 1.f));
  lambda = infinite ? splat(INFINITY) : lambda;
  lambda = positive ? lambda : (rho2 == zero ? splat(-INFINITY) : splat(NAN));
  // clamped_lambda, with each quad's bias
  lambda = lambda != lambda ? zero : lambda;
  lambda = lambda + bias;
  const F4 min_lod = splat(sampler.min_lod), max_lod = splat(sampler.max_lod);
  lambda = lambda < min_lod ? min_lod : lambda;  // std::max(lambda, min_lod)
  lambda = max_lod < lambda ? max_lod : lambda;  // std::min(lambda, max_lod)
  const I4 finite = (lambda > splat(-1e30f)) & (lambda < splat(1e30f));
  return finite ? lambda : (lambda > zero ? splat(1e30f) : splat(-1e30f));
}

}  // namespace pineda::raster
