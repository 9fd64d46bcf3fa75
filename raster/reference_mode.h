// PINEDA_REFERENCE=1 selects the reference mode when a renderer is created: one thread,
// triangles rasterized per pixel in double precision (reference_triangle.h), every fragment
// shaded by the scalar reference stage (reference_fragment.h). It is the ground truth that
// pineda-bench measures the fast path's error against.
#pragma once
#include <cstdlib>
#include <cstring>

namespace pineda::raster {

inline bool reference_mode_from_environment() {
  const char* v = std::getenv("PINEDA_REFERENCE");
  return v && *v && std::strcmp(v, "0") != 0;
}

}  // namespace pineda::raster
