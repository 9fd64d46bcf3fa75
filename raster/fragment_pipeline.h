// The fragment pipeline: texturing, alpha, stencil, depth, blending or logic op, masks and
// write-back, specialized at compile time on a FragmentKey.
#pragma once

#include "raster/draw_record.h"
#include "raster/simd_path.h"

namespace pineda::raster {

QuadRoutine select_quad_routine(const FragmentKey& key, SimdPath path = SimdPath::Best);

}  // namespace pineda::raster
