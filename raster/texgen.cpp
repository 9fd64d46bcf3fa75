#include "raster/texgen.h"

#include <cmath>

namespace pineda::raster {

bool TexGen::needs_normal() const {
  for (const TexGenCoord& c : coord)
    if (c.enabled && (c.mode == TexGenMode::SphereMap || c.mode == TexGenMode::NormalMap ||
                      c.mode == TexGenMode::ReflectionMap))
      return true;
  return false;
}

namespace {

// u: the unit vector from the eye to the vertex; r = u - 2 n (n . u).
glm::vec3 reflection(const TexGenInput& in) {
  const glm::vec3 e(in.eye);
  const float len = glm::length(e);
  const glm::vec3 u = len > 0.f ? e / len : e;
  return u - 2.f * in.normal * glm::dot(in.normal, u);
}

}  // namespace

void generate_texcoords(const TexGen& gen, const TexGenInput& in, float texcoord[4]) {
  bool have_reflection = false;
  glm::vec3 r;
  for (int i = 0; i < 4; ++i) {
    const TexGenCoord& c = gen.coord[i];
    if (!c.enabled) continue;
    switch (c.mode) {
      case TexGenMode::ObjectLinear: texcoord[i] = glm::dot(c.object_plane, in.object); break;
      case TexGenMode::EyeLinear: texcoord[i] = glm::dot(c.eye_plane, in.eye); break;
      case TexGenMode::NormalMap: texcoord[i] = i < 3 ? in.normal[i] : texcoord[i]; break;
      case TexGenMode::ReflectionMap:
      case TexGenMode::SphereMap: {
        if (!have_reflection) r = reflection(in);
        have_reflection = true;
        if (c.mode == TexGenMode::ReflectionMap) {
          if (i < 3) texcoord[i] = r[i];
          break;
        }
        if (i >= 2) break;  // sphere map defines s and t only
        const float m = 2.f * std::sqrt(r.x * r.x + r.y * r.y + (r.z + 1.f) * (r.z + 1.f));
        texcoord[i] = m > 0.f ? r[i] / m + 0.5f : 0.5f;
        break;
      }
    }
  }
}

}  // namespace pineda::raster
