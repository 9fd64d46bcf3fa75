// GL 1.4 point parameters (section 3.3): the derived point size.
#pragma once
#include <algorithm>
#include <cmath>

#include "raster/point_sprite.h"
#include "raster/raster_limits.h"

namespace pineda::raster {

struct PointParameters {
  float size_min = 0.f, size_max = float(kMaxPointSize);  // state/ starts it at its reported range
  float fade_threshold = 1.f;  // fades only under multisampling, which single-sampled buffers never do
  float attenuation[3] = {1.f, 0.f, 0.f};  // a, b, c of 1 / (a + b d + c d^2)
  bool size_per_vertex = false;  // each vertex brings its size (OpenGL ES 1.1's point size array)
  PointSprite sprite;

  // Whether the size depends on the vertex's distance (else one size serves the whole draw).
  bool attenuated() const { return attenuation[0] != 1.f || attenuation[1] != 0.f || attenuation[2] != 0.f; }
  // Whether each vertex gets its own size (ClipVertex::point_size).
  bool per_vertex() const { return attenuated() || size_per_vertex; }
};

// size * sqrt(1 / (a + b d + c d^2)), clamped to [size_min, size_max]. `eye_distance` is
// |z_eye|, as Mesa and piglit measure it. A negative denominator is taken by its magnitude
// (the ARB vertex program RSQ that Mesa evaluates it with does so); zero gives size_max.
inline float derived_point_size(const PointParameters& p, float size, float eye_distance) {
  const float d = eye_distance;
  const float q = std::fabs(p.attenuation[0] + p.attenuation[1] * d + p.attenuation[2] * d * d);
  const float derived = size / std::sqrt(q);
  return std::min(std::max(derived, p.size_min), p.size_max);
}

}  // namespace pineda::raster
