// The fragment pipeline: texturing, alpha, stencil, depth, blending or logic op, masks and
// write-back, specialized at compile time on a FragmentKey.
#pragma once

#include "raster/draw_record.h"

namespace pineda::raster {

QuadRoutine select_quad_routine(const FragmentKey& key);

}  // namespace pineda::raster
