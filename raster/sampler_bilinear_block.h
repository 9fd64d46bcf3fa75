// The bilinear RGBA8 sampler of sampler_bilinear8.h for a shader block's 16 lanes at once,
// when every quad of the block reads the same level or pair of levels (neighbouring quads
// mostly do): the same indices, weights and integer arithmetic per lane, so the same texels
// as four calls of the quad sampler.
#pragma once

#include "raster/mip_selection.h"
#include "raster/simd_path.h"
#include "raster/texture.h"

namespace pineda::raster {

constexpr int kBlockLanes = 16;

// out[c][lane]: channel c (RGBA, as stored) of each lane, in [0, 1], read at `choice`. Each
// vector of lanes is read from s and t before it is written, so out may be s or t.
using BlockSampler = void (*)(const TextureImage& image, const LevelChoice& choice, const float* s, const float* t,
                              float* const out[4]);

// The block sampler for an image and sampler that select_bilinear8_sampler takes.
BlockSampler select_bilinear8_block_sampler(const Sampler& sampler, SimdPath path = SimdPath::Best);

}  // namespace pineda::raster
