// GL_COMBINE texture environments: three sources through operands into one function, per
// RGB and alpha, then scaled and clamped.
#pragma once

#include "raster/tex_env.h"

namespace pineda::raster {

// Returns false, leaving `color` unchanged, when a source names a unit that is not enabled
// (undefined in the spec; Mesa's software path leaves the fragment alone too).
bool apply_tex_combine(const CombineState& combine, int index, const float env_color[4], const PixelTexels& texels,
                       const float primary[4], float color[4]);

}  // namespace pineda::raster
