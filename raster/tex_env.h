// The fixed-function texture environment (GL 1.5 tables 3.22 and 3.23).
#pragma once

#include "raster/texture.h"

namespace pineda::raster {

// color: the incoming fragment colour (Cf, Af), replaced by the unit's output.
// texel: the filtered texel as stored; the base format decides which components count.
void apply_tex_env(TexEnvMode mode, TexBaseFormat format, const float env_color[4], const float texel[4],
                   float color[4]);

}  // namespace pineda::raster
