// The GL 1.x lighting equation (GL 1.5 section 2.14.1) over a batch of vertices in lanes.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "raster/vertex_lanes.h"
#include "raster/vertex_transform.h"

namespace pineda::raster {

// What the equation needs of an enabled light that no vertex changes, worked out once per
// batch with the operations the per-vertex equation would use.
struct PreparedLight {
  const Light* light;
  bool local;                // position.w != 0
  glm::vec3 point;           // local: the position divided by w
  glm::vec3 direction;       // directional: the unit vector to the light
  bool spot;                 // spot_cutoff != 180
  glm::vec3 spot_direction;  // unit
  float cos_cutoff;
  bool fixed_half;           // directional and no local viewer: the half vector is the same everywhere
  glm::vec3 half_unit;
  bool half_nonzero;
};

struct PreparedLights {
  std::array<PreparedLight, kMaxLights> lights{};
  int count = 0;
};

PreparedLights prepare_lights(const Lighting& l);

// One face's material per lane (glColorMaterial makes it follow each vertex's colour).
struct LaneMaterial {
  LaneVec3 ambient, diffuse, specular, emission;
  Lanes alpha;  // the diffuse alpha
  float shininess;
};

// The material of the face (front or back) for the first n lanes, whose current colours are
// `colors[i]` (4 floats each).
void lane_material(const Lighting& l, bool front, const float* const* colors, int n, LaneMaterial& out);

// The lit colour (clamped) of the first n lanes, at eye positions `eye` with unit normals
// `normal`; with a separate specular colour the specular terms go to `specular` (clamped) and
// not into `color`.
void light_lanes(const Lighting& l, const PreparedLights& lights, const LaneMaterial& m, const LaneVec3& eye,
                 const LaneVec3& normal, int n, LaneVec4& color, LaneVec3& specular);

}  // namespace pineda::raster
