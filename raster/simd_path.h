// Which copy of the fragment routines runs: the best the CPU has (an AVX2 copy where it has
// AVX2), or the baseline x86-64 one (SSE2). Both perform the same operations (no FMA, no
// contraction), so the images are identical; the choice only trades speed.
// PINEDA_SIMD=baseline selects the baseline copy when a renderer is created.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace pineda::raster {

enum class SimdPath : uint8_t { Best, Baseline };

inline SimdPath simd_path_from_environment() {
  const char* v = std::getenv("PINEDA_SIMD");
  return v && std::strcmp(v, "baseline") == 0 ? SimdPath::Baseline : SimdPath::Best;
}

// Whether routines chosen for `path` take their AVX2 copy.
inline bool uses_avx2(SimdPath path) {
  static const bool has = __builtin_cpu_supports("avx2");
  return path == SimdPath::Best && has;
}

}  // namespace pineda::raster
