// Nearest sampling of RGBA8 Planar images for the four pixels of a quad: the texels the
// general sampler (sampler.h) picks, without its level-of-detail and border work. Selected
// once per draw; the general sampler takes the other keys.
#pragma once

#include "raster/sampler_bilinear8.h"
#include "raster/sampler_bilinear_block.h"
#include "raster/simd_path.h"
#include "raster/texture.h"

namespace pineda::raster {

// The specialized sampler, or null: only colour Planar images without sRGB decoding, NEAREST
// magnification and minification (level 0 whatever the level of detail), and REPEAT, CLAMP,
// CLAMP_TO_EDGE or MIRRORED_REPEAT on s and t qualify.
QuadSampler select_nearest8_sampler(const TextureImage& image, const Sampler& sampler);

// Its 16-lane form (shader_block_lanes.cpp) for an image and sampler it takes, or null
// (MIRRORED_REPEAT). The BlockLevels argument is not read: the level is 0.
BlockSampler select_nearest8_block_sampler(const Sampler& sampler, SimdPath path = SimdPath::Best);
// Its form for several lookups (sampler_bilinear_block.h's BlockLookupsSampler).
BlockLookupsSampler select_nearest8_block_lookups_sampler(const Sampler& sampler, SimdPath path = SimdPath::Best);

}  // namespace pineda::raster
