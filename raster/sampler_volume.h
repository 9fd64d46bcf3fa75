// Sampling of images with slices: 3D textures (GL 1.2 3.8.8, trilinear within a level) and
// cube maps (GL 1.3 3.8.6, a face chosen per pixel, then bilinear within that face).
#pragma once

#include "raster/mip_selection.h"
#include "raster/texture.h"

namespace pineda::raster {

void sample_volume_quad(const TextureImage& image, const Sampler& sampler, const float s[4], const float t[4],
                        const float r[4], float out[4][4]);
void sample_cube_quad(const TextureImage& image, const Sampler& sampler, const float s[4], const float t[4],
                      const float r[4], float out[4][4]);

// One pixel's sample from the levels `choice` names. `slice` >= 0 reads that slice only (a
// cube face) and ignores r; -1 addresses the slices by r with the R wrap mode.
void sample_slices(const TextureImage& image, const Sampler& sampler, const LevelChoice& choice, float s, float t,
                   float r, int slice, float out[4]);

}  // namespace pineda::raster
