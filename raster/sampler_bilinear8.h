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

}  // namespace pineda::raster
