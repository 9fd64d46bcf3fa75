// Which copy of the fragment routines runs: the best the CPU has (AVX-512 where a routine has
// such a copy and the CPU has AVX-512 F/BW/VL/DQ, else AVX2 where it has AVX2), or a lower one.
// All perform the same operations (no FMA, no contraction), so the images are identical; the
// choice only trades speed. PINEDA_SIMD=avx2 (at most AVX2) or PINEDA_SIMD=baseline (the
// baseline x86-64 copy, SSE2) is read when a renderer is created.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <cstring>

namespace pineda::raster {

enum class SimdPath : uint8_t { Best, Avx2, Baseline };

// The copies are compiled for their instruction sets with '#pragma GCC target', which clang
// ignores: its copies (the sanitizer build's) are all baseline code, so a copy that calls an
// instruction set's intrinsics asks this first.
#if defined(__clang__)
constexpr bool kCopiesHaveTheirTargets = false;
#else
constexpr bool kCopiesHaveTheirTargets = true;
#endif

inline SimdPath simd_path_from_environment() {
  const char* v = std::getenv("PINEDA_SIMD");
  if (v && std::strcmp(v, "baseline") == 0) return SimdPath::Baseline;
  if (v && std::strcmp(v, "avx2") == 0) return SimdPath::Avx2;
  return SimdPath::Best;
}

// Whether routines chosen for `path` take their AVX2 copy.
inline bool uses_avx2(SimdPath path) {
  static const bool has = __builtin_cpu_supports("avx2");
  return path != SimdPath::Baseline && has;
}

// Whether routines chosen for `path` take their AVX-512 copy, where they have one.
inline bool uses_avx512(SimdPath path) {
  static const bool has = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                          __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512dq");
  return path == SimdPath::Best && has;
}

}  // namespace pineda::raster
