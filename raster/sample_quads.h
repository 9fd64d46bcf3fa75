// The fixed-function SampleQuadRoutine (sample_targets.h): a multisampled draw's quads shaded
// once at their pixel centres (quad_colors.h), then alpha (to coverage), stencil, depth, blending
// and the write for each covered sample in its own plane, with the operations of the
// single-sampled routines (quad_ops.h; stencil and depth of all samples at once:
// sample_quad_tests.h). Fragment shaders have theirs in shader_quads.h.
#pragma once

#include "raster/draw_record.h"
#include "raster/simd_path.h"

namespace pineda::raster {

// The routine for a fixed-function draw of `key` into one draw buffer (several: draw_targets.h
// runs each draw buffer's).
SampleQuadRoutine select_sample_quad_routine(const FragmentKey& key, SimdPath path);

}  // namespace pineda::raster
