// Stencil and depth of a multisampled draw's 2x2 quad in every sample plane at once: 16 lanes,
// lane 4s + i for sample s's pixel i (sample_targets.h's masks word), with the tests, updates
// and depth values of the single-sampled quad operations (quad_ops.h's depth_stencil and
// depth_only) in each sample's plane. Baseline, AVX2 and AVX-512 copies, the same values.
#pragma once
#include <cstdint>

#include "raster/quad_vector.h"
#include "raster/sample_targets.h"
#include "raster/simd_path.h"

namespace pineda::raster {

struct FragmentKey;

// `lanes`: the samples' pixels to test of the quad at (x, y), whose pixel centres are (ox, oy)
// from the reference point. Each sample's depth is its primitive's (t.prim[s]) at those
// centres, or `fragment_z` (the shader's gl_FragDepth in depth-buffer units, per pixel) when
// given. `d` gives the draw's depth and stencil state, `p` the facing. Returns the lanes that
// pass both tests; writes the depth and stencil values they and the failing lanes leave.
using SampleQuadTests = uint16_t (*)(const DrawRecord& d, const PrimSetup& p, const SampleTargets& t, int x, int y,
                                     F4 ox, F4 oy, uint16_t lanes, const uint32_t* fragment_z);

// The tests of a draw of `key` (null when it has neither a depth nor a stencil test).
SampleQuadTests select_sample_quad_tests(const FragmentKey& key, SimdPath path);

}  // namespace pineda::raster
