// Asks for cache lines in the state that a store needs (PREFETCHW), ahead of the stores. The
// binning thread writes the queued primitives into a scene's memory that another thread read
// while it ran the scene before: each line then has to be taken back from that thread's cache,
// and stores waiting on those one after another had stalled binning (glsl_skinned, two
// threads: a third of the binning thread's time at the entry of setup_triangle, the first
// stores after add_prim's). Asked for ahead, the transfers overlap. A hint only: nothing read
// or written changes. Callers check the CPU once (Scene::prefetch_writes).
#pragma once
#include <cpuid.h>

#include <cstddef>

namespace pineda::raster {

inline bool cpu_has_prefetchw() {
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  return __get_cpuid(0x80000001u, &eax, &ebx, &ecx, &edx) && (ecx & bit_PRFCHW);
}

// The lines holding [p, p + bytes); only where cpu_has_prefetchw().
inline void prefetch_for_write(const void* p, size_t bytes) {
  constexpr size_t kLine = 64;
  const auto* first = static_cast<const char*>(p);
  const auto begin = reinterpret_cast<size_t>(first) & ~(kLine - 1);
  const auto end = reinterpret_cast<size_t>(first) + bytes;
  for (size_t line = begin; line < end; line += kLine) asm volatile("prefetchw %0" ::"m"(*reinterpret_cast<const char*>(line)));
}

}  // namespace pineda::raster
