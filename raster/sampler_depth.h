// Sampling of depth textures (GL 1.4: ARB_depth_texture, ARB_shadow, EXT_shadow_funcs).
#pragma once

#include "raster/sampler_bilinear_block.h"
#include "raster/simd_path.h"
#include "raster/texture.h"

namespace pineda::raster {

// As sample_quad for a Planar or Rect depth image. With the sampler's compare mode each texel read is
// compared with r[i] clamped to [0, 1] (r / q of the fragment) before filtering, as Mesa does;
// r may be null when the mode is off. The value v lands where the base format puts it:
// (v, v, v, 1) for Luminance, (v, v, v, v) for Intensity, (0, 0, 0, v) for Alpha.
void sample_depth_quad(const TextureImage& image, const Sampler& sampler, const float s[4], const float t[4],
                       const float r[4], float out[4][4]);

// Its 16-lane form for a shader's 2D lookups (shader_block_lanes.cpp), or null: only level 0 of
// a Planar depth image without comparison or swizzle, read by one filter, NEAREST or LINEAR, for
// both magnification and minification (so whatever the level of detail), REPEAT or
// CLAMP_TO_EDGE on s and t (CLAMP too for NEAREST). The BlockLevels argument is not read.
BlockSampler select_depth_block_sampler(const TextureImage& image, const Sampler& sampler,
                                        SimdPath path = SimdPath::Best);

}  // namespace pineda::raster
