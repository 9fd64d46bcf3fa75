// The varyings of a shader's fragment block (16 lanes) interpolated in one pass per varying,
// over vectors as wide as the instruction set has: the same operations per lane as
// eval_plane (fragment_extras.h), so the same values on every path.
#pragma once

#include "raster/prim_setup.h"
#include "raster/simd_path.h"

namespace pineda::raster {

constexpr int kVaryingLanes = 16;

// For each lane l at (ox[l], oy[l]) relative to the primitive's reference point:
// w[l] = inv_w's plane there, and out[v][l] = plane v there, times 1 / w[l] when perspective.
using VaryingInterpolator = void (*)(const Plane* planes, int count, const Plane& inv_w, bool perspective,
                                     const float* ox, const float* oy, float (*out)[kVaryingLanes], float* w);

VaryingInterpolator select_varying_interpolator(SimdPath path);

// Four quads of a block, each from its own primitive (a dense mesh's triangles of a pixel or
// two): lanes 4j to 4j + 3 take quad j's planes.
struct QuadPlanes {
  const Plane* planes[4];
  const Plane* inv_w[4];
  bool perspective[4];
};

// What VaryingInterpolator gives each primitive's quads, in one pass over the lanes instead of
// one per primitive.
using QuadVaryingInterpolator = void (*)(const QuadPlanes& quads, int count, const float* ox, const float* oy,
                                         float (*out)[kVaryingLanes], float* w);

QuadVaryingInterpolator select_quad_varying_interpolator(SimdPath path);

}  // namespace pineda::raster
