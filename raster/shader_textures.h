// Texture lookups of shaders (shader::TextureAccess) over the fixed-function samplers: the
// draw's texture units, 16 lanes at a time, level of detail from each 2x2 quad of lanes.
#pragma once
#include <array>
#include <cstdint>

#include "raster/sampler_bilinear8.h"
#include "raster/sampler_bilinear_block.h"
#include "raster/texture.h"
#include "shader/program.h"

namespace pineda::raster {

// Lives on one thread's stack for a stretch of one draw (its units do not change meanwhile), so
// the fast samplers of a unit are chosen at its first 2D lookup and kept.
class UnitTextureAccess final : public shader::TextureAccess {
 public:
  explicit UnitTextureAccess(const std::array<TextureUnit, kMaxTextureImageUnits>& units) : units_(units) {}
  // A unit without a complete texture of the sampler's kind reads (0, 0, 0, 1).
  void sample(int unit, shader::SamplerKind kind, const float (*coords)[shader::kLanes], shader::LodMode mode,
              const float* lod, shader::LaneMask live, float (*out)[shader::kLanes]) const override;
  bool sample_2d_block(int unit, const float* s, const float* t, shader::LaneMask live,
                       float* const out[4]) const override;

 private:
  // The fast quad and block samplers of a unit's image for 2D lookups (null: none fits).
  struct FastSamplers {
    QuadSampler quad;
    BlockSampler block;
    // sample_2d_block's whole route: the unit's 2D image, whose block sampler reads level 0
    // for every quad (no mipmap filter); null when the route needs more.
    const TextureImage* level_zero_image;
  };
  const FastSamplers& fast_samplers(int unit, const TextureImage& image) const;

  const std::array<TextureUnit, kMaxTextureImageUnits>& units_;
  // Entry i is set when bit i of `chosen_` is: made for each row of quads, the object is not
  // zeroed whole (GCC's rep stos for it was a tenth of shading a small triangle's row).
  mutable uint32_t chosen_ = 0;
  mutable std::array<FastSamplers, kMaxTextureImageUnits> fast_;
};

}  // namespace pineda::raster
