// Sampling of depth textures (GL 1.4: ARB_depth_texture, ARB_shadow, EXT_shadow_funcs).
#pragma once

#include "raster/texture.h"

namespace pineda::raster {

// As sample_quad for a Planar or Rect depth image. With the sampler's compare mode each texel read is
// compared with r[i] clamped to [0, 1] (r / q of the fragment) before filtering, as Mesa does;
// r may be null when the mode is off. The value v lands where the base format puts it:
// (v, v, v, 1) for Luminance, (v, v, v, v) for Intensity, (0, 0, 0, v) for Alpha.
void sample_depth_quad(const TextureImage& image, const Sampler& sampler, const float s[4], const float t[4],
                       const float r[4], float out[4][4]);

}  // namespace pineda::raster
