// Texture coordinate generation (GL 1.5 section 2.11.4): per unit, each of s, t, r, q either
// passes the vertex's coordinate through or is generated from its position or normal.
#pragma once
#include <array>
#include <cstdint>

#include <glm/glm.hpp>

namespace pineda::raster {

enum class TexGenMode : uint8_t { ObjectLinear, EyeLinear, SphereMap, NormalMap, ReflectionMap };

struct TexGenCoord {
  bool enabled = false;
  TexGenMode mode = TexGenMode::EyeLinear;
  glm::vec4 object_plane{0, 0, 0, 0};
  glm::vec4 eye_plane{0, 0, 0, 0};  // already multiplied by the inverse modelview of its time
};

struct TexGen {
  std::array<TexGenCoord, 4> coord;  // s, t, r, q
  bool any() const { return coord[0].enabled || coord[1].enabled || coord[2].enabled || coord[3].enabled; }
  // Whether a mode needs the eye-space normal.
  bool needs_normal() const;
};

// What generation reads of one vertex, in object and eye coordinates.
struct TexGenInput {
  glm::vec4 object;
  glm::vec4 eye;
  glm::vec3 normal;  // eye space, as lighting uses it
};

// Replaces the enabled components of `texcoord` (s, t, r, q) with generated values.
void generate_texcoords(const TexGen& gen, const TexGenInput& in, float texcoord[4]);

}  // namespace pineda::raster
