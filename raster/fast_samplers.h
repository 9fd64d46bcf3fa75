// The fast 2D samplers (8-bit bilinear or nearest texels; a block form alone for depth images)
// a shader's lookups of one texture unit take, chosen once for a draw
// (DrawRecord::shader_samplers) rather than by every row of quads that samples it (the choice
// was 2% of glsl_sprites).
#pragma once
#include "raster/sampler.h"
#include "raster/sampler_bilinear8.h"
#include "raster/sampler_bilinear_block.h"
#include "raster/simd_path.h"
#include "raster/texture.h"

namespace pineda::raster {

// Null members: none fits. No member initializers (UnitTextureAccess::fast_ says why):
// value-initialize (`{}`) for none.
struct FastSamplers {
  QuadSampler quad;
  BlockSampler block;
  BlockLookupsSampler lookups;  // the block sampler's form for several lookups
  // TextureAccess::sample_2d_block's whole route: the unit's 2D image, whose block sampler reads
  // level 0 for every quad (no mipmap filter); null when the route needs more.
  const TextureImage* level_zero_image;
};

FastSamplers choose_fast_samplers(const TextureImage& image, const Sampler& sampler, SimdPath path);

}  // namespace pineda::raster
