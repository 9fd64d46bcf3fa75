// Texture sampling for a 2x2 quad: one level of detail from the quad's coordinate
// differences, then per-pixel filtering with the sampler's wrap modes.
#pragma once

#include "raster/texture.h"

namespace pineda::raster {

// s[i], t[i], r[i]: coordinates of quad pixel i (0: x,y  1: x+1,y  2: x,y+1  3: x+1,y+1);
// r is read by Volume and Cube images and for depth comparisons (null is fine for a Planar or
// Rect one without).
// out[i]: RGBA in [0, 1], as stored (the base format is applied by the texture environment).
void sample_quad(const TextureImage& image, const Sampler& sampler, const float s[4], const float t[4],
                 const float r[4], float out[4][4]);
// The same for a Planar or Rect image.
void sample_quad(const TextureImage& image, const Sampler& sampler, const float s[4], const float t[4],
                 float out[4][4]);

// The level of detail for a quad, before clamping to the sampler's range (-inf when the
// coordinates do not change across the quad).
float quad_lambda(const TextureLevel& base, const float s[4], const float t[4]);
// The same with the scale from coordinates to texels given: 1 for a rectangle's texel coordinates.
float quad_lambda(float width, float height, const float s[4], const float t[4]);

}  // namespace pineda::raster
