// The fixed-function texture environment (GL 1.5 tables 3.22 and 3.23, and GL_COMBINE).
#pragma once

#include "raster/texture.h"

namespace pineda::raster {

// color: the incoming fragment colour (Cf, Af), replaced by the unit's output.
// texel: the filtered texel as stored; the base format decides which components count.
void apply_tex_env(TexEnvMode mode, TexBaseFormat format, const float env_color[4], const float texel[4],
                   float color[4]);

// One pixel's filtered texel on every unit, null for a unit that is not enabled.
struct PixelTexels {
  const float* unit[kMaxTextureUnits] = {};
};

// The environment of unit `index` (enabled) for one pixel: `color` is the previous unit's
// output (the primary colour for the first enabled unit), replaced by this unit's output.
void apply_unit_env(const TextureUnit& unit, int index, const PixelTexels& texels, const float primary[4],
                    float color[4]);

}  // namespace pineda::raster
