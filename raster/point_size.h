// GL 1.4 point parameters (section 3.3): the derived point size.
#pragma once
#include <algorithm>
#include <cmath>

#include "raster/point_sprite.h"
#include "raster/raster_limits.h"

namespace pineda::raster {

struct PointParameters {
  float size_min = 0.f, size_max = float(kMaxPointSize);  // state/ starts it at its reported range
  float fade_threshold = 1.f;  // fades only multisampled points (point_fade)
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

// GL 1.4 section 3.3, multisampled points only: a point whose derived size is under the fade
// threshold is drawn at the threshold's size, its alpha multiplied by (size / threshold)^2.
struct PointFade {
  float size = 1.f, fade = 1.f;
};
inline PointFade point_fade(float derived, float threshold) {
  if (!(derived < threshold)) return {derived, 1.f};
  const float ratio = derived / threshold;
  return {threshold, ratio * ratio};
}

}  // namespace pineda::raster
