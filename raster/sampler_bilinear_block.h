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

// The level, or pair of levels, every quad of a block reads, and each quad's weight of the
// second level of a pair (its LevelChoice::blend: neighbouring quads mostly share the levels,
// not the weight).
struct BlockLevels {
  int first = 0;
  bool two = false;
  float blend[4] = {0.f, 0.f, 0.f, 0.f};  // quad q: lanes 4q to 4q + 3
};

// out[c][lane]: channel c of each lane, in [0, 1], read at `levels`, as a shader reads it (GL
// 2.0 table 3.20: the image's base format applied to the stored RGBA). Each vector of lanes is
// read from s and t before it is written, so out may be s or t.
using BlockSampler = void (*)(const TextureImage& image, const BlockLevels& levels, const float* s, const float* t,
                              float* const out[4]);

// The block sampler for an image and sampler that select_bilinear8_sampler takes.
BlockSampler select_bilinear8_block_sampler(const Sampler& sampler, SimdPath path = SimdPath::Best);

// `count` lookups of level 0 of one image, lookup k at s[k] and t[k] into out[k], as the block
// sampler makes each (BlockLevels{}) in turn, where no lookup reads what an earlier one writes:
// the AVX-512 copy reads up to kMaxBlockLookups lookups' coordinates before it writes, and reads
// the texels they share once (a filter kernel's taps).
constexpr int kMaxBlockLookups = 16;
using BlockLookupsSampler = void (*)(const TextureImage& image, int count, const float* const* s, const float* const* t,
                                     float* const (*out)[4]);
BlockLookupsSampler select_bilinear8_block_lookups_sampler(const Sampler& sampler, SimdPath path = SimdPath::Best);

}  // namespace pineda::raster
