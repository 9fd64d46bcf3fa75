#include "raster/vertex_transform.h"

#include <algorithm>
#include <cmath>

namespace pineda::raster {
namespace {

struct MaterialColors {
  glm::vec4 ambient, diffuse, specular, emission;
  float shininess;
};

MaterialColors material_for(const Lighting& l, const Material& m, bool is_front, const float* color) {
  MaterialColors c{m.ambient, m.diffuse, m.specular, m.emission, m.shininess};
  const ColorMaterial& cm = l.color_material;
  if (cm.enabled && (is_front ? cm.front : cm.back)) {
    const glm::vec4 current(color[0], color[1], color[2], color[3]);
    if (cm.ambient) c.ambient = current;
    if (cm.diffuse) c.diffuse = current;
    if (cm.specular) c.specular = current;
    if (cm.emission) c.emission = current;
  }
  return c;
}

// The GL 1.x lighting equation (GL 1.5 spec, section 2.14.1) for one face. With a separate
// specular colour the specular terms go to `specular` instead of the result.
glm::vec4 light_vertex(const Lighting& l, const MaterialColors& m, const glm::vec3& eye_pos,
                       const glm::vec3& normal, glm::vec3& specular) {
  glm::vec3 color = glm::vec3(m.emission) + glm::vec3(m.ambient) * glm::vec3(l.model_ambient);
  specular = glm::vec3(0.f);
  for (const Light& light : l.lights) {
    if (!light.enabled) continue;
    glm::vec3 to_light;
    float attenuation = 1.f;
    if (light.position.w != 0.f) {
      to_light = glm::vec3(light.position) / light.position.w - eye_pos;
      const float d = glm::length(to_light);
      const float denom = light.constant_attenuation + light.linear_attenuation * d +
                          light.quadratic_attenuation * d * d;
      attenuation = denom > 0.f ? 1.f / denom : 1.f;
      if (d > 0.f) to_light /= d;
    } else {
      to_light = glm::normalize(glm::vec3(light.position));
    }
    float spot = 1.f;
    if (light.spot_cutoff != 180.f) {
      const float cos_angle = glm::dot(-to_light, glm::normalize(light.spot_direction));
      const float cos_cutoff = std::cos(glm::radians(light.spot_cutoff));
      spot = cos_angle >= cos_cutoff ? std::pow(std::max(cos_angle, 0.f), light.spot_exponent) : 0.f;
    }
    const float factor = attenuation * spot;
    if (factor == 0.f) continue;
    glm::vec3 contribution = glm::vec3(m.ambient) * glm::vec3(light.ambient);
    glm::vec3 spec_contribution(0.f);
    const float n_dot_l = glm::dot(normal, to_light);
    if (n_dot_l > 0.f) {
      contribution += n_dot_l * glm::vec3(m.diffuse) * glm::vec3(light.diffuse);
      const glm::vec3 to_eye = l.local_viewer ? glm::normalize(-eye_pos) : glm::vec3(0, 0, 1);
      const glm::vec3 half = to_light + to_eye;
      const float half_len = glm::length(half);
      if (half_len > 0.f) {
        const float n_dot_h = glm::dot(normal, half / half_len);
        if (n_dot_h > 0.f) {
          const float spec = m.shininess == 0.f ? 1.f : std::pow(n_dot_h, m.shininess);
          spec_contribution = spec * glm::vec3(m.specular) * glm::vec3(light.specular);
        }
      }
    }
    if (l.separate_specular) {
      color += factor * contribution;
      specular += factor * spec_contribution;
    } else {
      color += factor * (contribution + spec_contribution);
    }
  }
  specular = glm::clamp(specular, 0.f, 1.f);
  return glm::vec4(glm::clamp(color, 0.f, 1.f), std::clamp(m.diffuse.a, 0.f, 1.f));
}

void store(float* dst, const glm::vec4& v) {
  dst[0] = v.x;
  dst[1] = v.y;
  dst[2] = v.z;
  dst[3] = v.w;
}

void store3(float* dst, const glm::vec3& v) {
  dst[0] = v.x;
  dst[1] = v.y;
  dst[2] = v.z;
}

// Which intermediate values the enabled stages read.
struct Needs {
  bool eye = false, normal = false, texgen = false;
};

Needs needs_of(const Transform& t) {
  const VertexExtras& x = t.extras;
  Needs n;
  n.normal = t.lighting.enabled;
  for (int u = 0; u < t.texture_units; ++u) {
    n.texgen |= x.texgen[u].any();
    n.normal |= x.texgen[u].needs_normal();
  }
  n.eye = t.lighting.enabled || (x.fog && !x.fog_from_coord) || x.clip_planes != 0 || n.texgen || x.point_attenuation;
  return n;
}

}  // namespace

void transform_vertices(const Transform& t, std::span<const VertexInput> in, std::vector<ClipVertex>& out) {
  out.resize(in.size());
  transform_vertices(t, in, std::span<ClipVertex>(out));
}

void transform_vertices(const Transform& t, std::span<const VertexInput> in, std::span<ClipVertex> out) {
  const Lighting& lighting = t.lighting;
  const VertexExtras& x = t.extras;
  const Needs needs = needs_of(t);
  for (size_t i = 0; i < in.size(); ++i) {
    const VertexInput& v = in[i];
    ClipVertex& o = out[i];
    const glm::vec4 obj(v.position[0], v.position[1], v.position[2], v.position[3]);
    store(o.clip, t.modelview_projection * obj);
    o.edge_flag = v.edge_flag;
    const glm::vec4 eye4 = needs.eye ? t.modelview * obj : glm::vec4(0.f);
    glm::vec3 normal(0.f);
    if (needs.normal) {
      normal = t.normal_matrix * glm::vec3(v.normal[0], v.normal[1], v.normal[2]);
      normal *= t.rescale_factor;
      if (t.normalize) {
        const float len = glm::length(normal);
        if (len > 0.f) normal /= len;
      }
    }

    if (lighting.enabled) {
      const glm::vec3 eye_pos = eye4.w != 0.f ? glm::vec3(eye4) / eye4.w : glm::vec3(eye4);
      glm::vec3 specular;
      store(o.color, light_vertex(lighting, material_for(lighting, lighting.front, true, v.color), eye_pos, normal,
                                  specular));
      store3(o.secondary, specular);
      if (lighting.two_side) {
        store(o.back_color, light_vertex(lighting, material_for(lighting, lighting.back, false, v.color), eye_pos,
                                         -normal, specular));
        store3(o.back_secondary, specular);
      } else {
        std::copy(o.color, o.color + 4, o.back_color);
        std::copy(o.secondary, o.secondary + 3, o.back_secondary);
      }
    } else {
      for (int c = 0; c < 4; ++c) o.color[c] = o.back_color[c] = std::clamp(v.color[c], 0.f, 1.f);
      if (x.color_sum)
        for (int c = 0; c < 3; ++c) o.secondary[c] = o.back_secondary[c] = std::clamp(v.secondary_color[c], 0.f, 1.f);
    }
    if (x.fog) o.fog = std::fabs(x.fog_from_coord ? v.fog_coord : eye4.z);
    if (x.point_attenuation)
      o.point_size = derived_point_size(x.point, x.point.size_per_vertex ? v.point_size : x.point_size, std::fabs(eye4.z));
    for (uint32_t planes = x.clip_planes; planes; planes &= planes - 1) {
      const int p = __builtin_ctz(planes);
      o.clip_distance[p] = glm::dot(x.clip_plane_eye[p], eye4);
    }

    for (int u = 0; u < t.texture_units; ++u) {
      float coords[4] = {v.texcoord[u][0], v.texcoord[u][1], v.texcoord[u][2], v.texcoord[u][3]};
      if (needs.texgen && x.texgen[u].any()) generate_texcoords(x.texgen[u], {obj, eye4, normal}, coords);
      const glm::vec4 tc(coords[0], coords[1], coords[2], coords[3]);
      store(o.texcoord[u], t.texture_matrix_identity[u] ? tc : t.texture_matrix[u] * tc);
    }
  }
}

}  // namespace pineda::raster
