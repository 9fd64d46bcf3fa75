// Bilinear sampling of RGBA8 Planar images for the four pixels of a quad at once, in integers
// with 8-bit fractions as llvmpipe's unorm8 path does: texel indices and weights per lane,
// texels gathered, weighted sums exact in 32 bits, one LOD per quad. Specialized per wrap mode
// pair; selected once per draw for the keys it covers, the float sampler (sampler.h) for the rest.
#pragma once

#include "raster/mip_selection.h"
#include "raster/quad_vector.h"
#include "raster/simd_path.h"
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

// The level or pair of levels that sampler reads for the quad at (s, t).
LevelChoice bilinear8_quad_levels(const TextureImage& image, const Sampler& sampler, F4 s, F4 t);

}  // namespace pineda::raster
