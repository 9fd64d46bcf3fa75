// Texture lookups of shaders (shader::TextureAccess) over the fixed-function samplers: the
// draw's texture units, 16 lanes at a time, level of detail from each 2x2 quad of lanes.
#pragma once
#include <array>
#include <cstdint>

#include "raster/fast_samplers.h"
#include "raster/texture.h"
#include "shader/program.h"

namespace pineda::raster {

// Lives on one thread's stack for a stretch of one draw (its units do not change meanwhile), so
// the fast samplers of a unit are chosen at its first 2D lookup and kept; or they come chosen
// for the draw (`chosen`, each unit's for its image and sampler in `units`).
class UnitTextureAccess final : public shader::TextureAccess {
 public:
  explicit UnitTextureAccess(const std::array<TextureUnit, kMaxTextureImageUnits>& units,
                             const std::array<FastSamplers, kMaxTextureImageUnits>* chosen = nullptr)
      : units_(units), chosen_samplers_(chosen) {}
  // A unit without a complete texture of the sampler's kind reads (0, 0, 0, 1).
  void sample(int unit, shader::SamplerKind kind, const float (*coords)[shader::kLanes], shader::LodMode mode,
              const float* lod, shader::LaneMask live, float (*out)[shader::kLanes]) const override;
  bool sample_2d_block(int unit, const float* s, const float* t, shader::LaneMask live,
                       float* const out[4]) const override;
  bool sample_2d_blocks(int unit, int count, const float* const* s, const float* const* t, shader::LaneMask live,
                        float* const (*out)[4]) const override;

 private:
  // The fast quad and block samplers of a unit's image for 2D lookups.
  const FastSamplers& fast_samplers(int unit, const TextureImage& image) const;
  const FastSamplers* level_zero_route(int unit) const;

  const std::array<TextureUnit, kMaxTextureImageUnits>& units_;
  const std::array<FastSamplers, kMaxTextureImageUnits>* chosen_samplers_;
  // Entry i is set when bit i of `chosen_` is: made for each row of quads, the object is not
  // zeroed whole (GCC's rep stos for it was a tenth of shading a small triangle's row).
  mutable uint32_t chosen_ = 0;
  mutable std::array<FastSamplers, kMaxTextureImageUnits> fast_;
};

}  // namespace pineda::raster
