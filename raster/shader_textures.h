// Texture lookups of shaders (shader::TextureAccess) over the fixed-function samplers: the
// draw's texture units, 16 lanes at a time, level of detail from each 2x2 quad of lanes.
#pragma once
#include <array>

#include "raster/texture.h"
#include "shader/program.h"

namespace pineda::raster {

class UnitTextureAccess final : public shader::TextureAccess {
 public:
  explicit UnitTextureAccess(const std::array<TextureUnit, kMaxTextureImageUnits>& units) : units_(units) {}
  // A unit without a complete texture of the sampler's kind reads (0, 0, 0, 1).
  void sample(int unit, shader::SamplerKind kind, const float (*coords)[shader::kLanes], shader::LodMode mode,
              const float* lod, shader::LaneMask live, float (*out)[shader::kLanes]) const override;

 private:
  const std::array<TextureUnit, kMaxTextureImageUnits>& units_;
};

}  // namespace pineda::raster
