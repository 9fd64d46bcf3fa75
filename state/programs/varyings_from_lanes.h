// The vertex shader's varyings (and clip positions), one row of kLanes floats per varying, into
// each vertex's floats in a row: 4 vertices by 4 varyings at a time through a 4x4 transpose (one
// float at a time, this copy took most of run_vertex_shader's own time in glmark2's terrain).
#pragma once
#include <xmmintrin.h>

#include <cstddef>

#include "raster/vertex.h"
#include "shader/program.h"

namespace pineda {

// lanes[k * kLanes + i] (varying k of vertex i, i < vertices <= kLanes) -> out[i * nv + k].
inline void varyings_from_lanes(const float* lanes, int vertices, int nv, float* out) {
  constexpr size_t kLanes = shader::kLanes;
  const size_t row = static_cast<size_t>(nv);
  int i = 0;
  for (; i + 4 <= vertices; i += 4) {
    int k = 0;
    for (; k + 4 <= nv; k += 4) {
      const float* at = lanes + static_cast<size_t>(k) * kLanes + static_cast<size_t>(i);
      __m128 v0 = _mm_loadu_ps(at), v1 = _mm_loadu_ps(at + kLanes), v2 = _mm_loadu_ps(at + 2 * kLanes),
             v3 = _mm_loadu_ps(at + 3 * kLanes);
      _MM_TRANSPOSE4_PS(v0, v1, v2, v3);  // vN: vertex i + N's varyings k to k + 3
      float* to = out + static_cast<size_t>(i) * row + static_cast<size_t>(k);
      _mm_storeu_ps(to, v0);
      _mm_storeu_ps(to + row, v1);
      _mm_storeu_ps(to + 2 * row, v2);
      _mm_storeu_ps(to + 3 * row, v3);
    }
    for (; k < nv; ++k)
      for (int j = i; j < i + 4; ++j) out[size_t(j) * row + size_t(k)] = lanes[size_t(k) * kLanes + size_t(j)];
  }
  for (; i < vertices; ++i)
    for (int k = 0; k < nv; ++k) out[size_t(i) * row + size_t(k)] = lanes[size_t(k) * kLanes + size_t(i)];
}

// lanes[k * kLanes + i] (component k of vertex i's clip position, i < vertices <= kLanes) ->
// out[i].clip[k], four vertices at a time as above.
inline void positions_from_lanes(const float* lanes, int vertices, raster::ClipVertex* out) {
  constexpr size_t kLanes = shader::kLanes;
  int i = 0;
  for (; i + 4 <= vertices; i += 4) {
    const float* at = lanes + static_cast<size_t>(i);
    __m128 v0 = _mm_loadu_ps(at), v1 = _mm_loadu_ps(at + kLanes), v2 = _mm_loadu_ps(at + 2 * kLanes),
           v3 = _mm_loadu_ps(at + 3 * kLanes);
    _MM_TRANSPOSE4_PS(v0, v1, v2, v3);
    _mm_storeu_ps(out[i].clip, v0);
    _mm_storeu_ps(out[i + 1].clip, v1);
    _mm_storeu_ps(out[i + 2].clip, v2);
    _mm_storeu_ps(out[i + 3].clip, v3);
  }
  for (; i < vertices; ++i)
    for (int k = 0; k < 4; ++k) out[i].clip[k] = lanes[size_t(k) * kLanes + size_t(i)];
}

}  // namespace pineda
