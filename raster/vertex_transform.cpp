#include "raster/vertex_transform.h"

#include <algorithm>
#include <cmath>

#include "raster/vertex_lighting.h"

namespace pineda::raster {
namespace {

void store(float* dst, const glm::vec4& v) {
  dst[0] = v.x;
  dst[1] = v.y;
  dst[2] = v.z;
  dst[3] = v.w;
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
  const PreparedLights prepared = lighting.enabled ? prepare_lights(lighting) : PreparedLights{};
  const glm::mat4& mvp = t.modelview_projection;
  const glm::mat4& mv = t.modelview;
  const glm::mat3& nm = t.normal_matrix;
  LaneVec4 obj;
  // Zero where not needed, as each vertex alone would have them (set once: no batch writes them).
  LaneVec4 eye4{};
  LaneVec3 normal{}, eye_pos;
  LaneMaterial material;
  LaneVec4 color;
  LaneVec3 specular;
  const float* colors[kVertexLanes];
  const bool in_lanes = needs.eye || needs.normal;  // positions in lanes (else only clip positions)
  const bool per_vertex_extras = x.fog || x.point_attenuation || x.clip_planes != 0 || t.texture_units > 0;
  for (size_t base = 0; base < in.size(); base += kVertexLanes) {
    const int n = static_cast<int>(std::min<size_t>(kVertexLanes, in.size() - base));
    const VertexInput* v = &in[base];
    ClipVertex* o = &out[base];
    if (!in_lanes) {
      // Only the clip position: turning the vertices into lanes and back would cost more than
      // the lanes save. GLM's product, which the lanes below reproduce operation by operation.
      for (int i = 0; i < n; ++i) {
        store(o[i].clip, mvp * glm::vec4(v[i].position[0], v[i].position[1], v[i].position[2], v[i].position[3]));
        o[i].edge_flag = v[i].edge_flag;
      }
    }
    for (int i = 0; i < n && in_lanes; ++i) {
      obj.x[i] = v[i].position[0];
      obj.y[i] = v[i].position[1];
      obj.z[i] = v[i].position[2];
      obj.w[i] = v[i].position[3];
    }
    // m * (x, y, z, w) as GLM computes it: (m0 x + m1 y) + (m2 z + m3 w), column by column.
    auto transform = [&](const glm::mat4& m, int row, Lanes& result) {
      const float a = m[0][row], b = m[1][row], c = m[2][row], d = m[3][row];
      for (int i = 0; i < n; ++i) result[i] = (a * obj.x[i] + b * obj.y[i]) + (c * obj.z[i] + d * obj.w[i]);
    };
    if (in_lanes) {
      LaneVec4 clip;
      transform(mvp, 0, clip.x);
      transform(mvp, 1, clip.y);
      transform(mvp, 2, clip.z);
      transform(mvp, 3, clip.w);
      for (int i = 0; i < n; ++i) {
        o[i].clip[0] = clip.x[i];
        o[i].clip[1] = clip.y[i];
        o[i].clip[2] = clip.z[i];
        o[i].clip[3] = clip.w[i];
        o[i].edge_flag = v[i].edge_flag;
      }
    }
    if (needs.eye) {
      transform(mv, 0, eye4.x);
      transform(mv, 1, eye4.y);
      transform(mv, 2, eye4.z);
      transform(mv, 3, eye4.w);
    }
    if (needs.normal) {
      const float r = t.rescale_factor;
      LaneVec3 in_normal;
      for (int i = 0; i < n; ++i) {
        in_normal.x[i] = v[i].normal[0];
        in_normal.y[i] = v[i].normal[1];
        in_normal.z[i] = v[i].normal[2];
      }
      for (int i = 0; i < n; ++i) {
        const float nx = in_normal.x[i], ny = in_normal.y[i], nz = in_normal.z[i];
        float a = (nm[0][0] * nx + nm[1][0] * ny) + nm[2][0] * nz;
        float b = (nm[0][1] * nx + nm[1][1] * ny) + nm[2][1] * nz;
        float c = (nm[0][2] * nx + nm[1][2] * ny) + nm[2][2] * nz;
        a *= r;
        b *= r;
        c *= r;
        if (t.normalize) {  // a select, so that the loop vectorizes: x / 1 is x
          const float len = std::sqrt(a * a + b * b + c * c);
          const float divisor = len > 0.f ? len : 1.f;
          a /= divisor;
          b /= divisor;
          c /= divisor;
        }
        normal.x[i] = a;
        normal.y[i] = b;
        normal.z[i] = c;
      }
    }

    if (lighting.enabled) {
      for (int i = 0; i < n; ++i) {
        const float w = eye4.w[i];
        const bool divide = w != 0.f;
        eye_pos.x[i] = divide ? eye4.x[i] / w : eye4.x[i];
        eye_pos.y[i] = divide ? eye4.y[i] / w : eye4.y[i];
        eye_pos.z[i] = divide ? eye4.z[i] / w : eye4.z[i];
      }
      for (int i = 0; i < n; ++i) colors[i] = v[i].color;
      auto store_lit = [&](float (ClipVertex::*rgba)[4], float (ClipVertex::*rgb)[3]) {
        for (int i = 0; i < n; ++i) {
          float* c = o[i].*rgba;
          c[0] = color.x[i];
          c[1] = color.y[i];
          c[2] = color.z[i];
          c[3] = color.w[i];
          float* s = o[i].*rgb;
          s[0] = specular.x[i];
          s[1] = specular.y[i];
          s[2] = specular.z[i];
        }
      };
      lane_material(lighting, true, colors, n, material);
      light_lanes(lighting, prepared, material, eye_pos, normal, n, color, specular);
      store_lit(&ClipVertex::color, &ClipVertex::secondary);
      if (lighting.two_side) {
        LaneVec3 back_normal;
        for (int i = 0; i < n; ++i) {
          back_normal.x[i] = -normal.x[i];
          back_normal.y[i] = -normal.y[i];
          back_normal.z[i] = -normal.z[i];
        }
        lane_material(lighting, false, colors, n, material);
        light_lanes(lighting, prepared, material, eye_pos, back_normal, n, color, specular);
        store_lit(&ClipVertex::back_color, &ClipVertex::back_secondary);
      } else {
        for (int i = 0; i < n; ++i) {
          std::copy(o[i].color, o[i].color + 4, o[i].back_color);
          std::copy(o[i].secondary, o[i].secondary + 3, o[i].back_secondary);
        }
      }
    } else {
      for (int i = 0; i < n; ++i) {
        for (int c = 0; c < 4; ++c) o[i].color[c] = o[i].back_color[c] = std::clamp(v[i].color[c], 0.f, 1.f);
        if (x.color_sum)
          for (int c = 0; c < 3; ++c)
            o[i].secondary[c] = o[i].back_secondary[c] = std::clamp(v[i].secondary_color[c], 0.f, 1.f);
      }
    }

    if (!per_vertex_extras) continue;
    for (int i = 0; i < n; ++i) {
      const glm::vec4 eye(eye4.x[i], eye4.y[i], eye4.z[i], eye4.w[i]);
      if (x.fog) o[i].fog = std::fabs(x.fog_from_coord ? v[i].fog_coord : eye.z);
      if (x.point_attenuation)
        o[i].point_size =
            derived_point_size(x.point, x.point.size_per_vertex ? v[i].point_size : x.point_size, std::fabs(eye.z));
      for (uint32_t planes = x.clip_planes; planes; planes &= planes - 1) {
        const int p = __builtin_ctz(planes);
        o[i].clip_distance[p] = glm::dot(x.clip_plane_eye[p], eye);
      }
      for (int u = 0; u < t.texture_units; ++u) {
        float coords[4] = {v[i].texcoord[u][0], v[i].texcoord[u][1], v[i].texcoord[u][2], v[i].texcoord[u][3]};
        if (needs.texgen && x.texgen[u].any()) {
          const glm::vec4 position(obj.x[i], obj.y[i], obj.z[i], obj.w[i]);
          generate_texcoords(x.texgen[u], {position, eye, glm::vec3(normal.x[i], normal.y[i], normal.z[i])}, coords);
        }
        const glm::vec4 tc(coords[0], coords[1], coords[2], coords[3]);
        store(o[i].texcoord[u], t.texture_matrix_identity[u] ? tc : t.texture_matrix[u] * tc);
      }
    }
  }
}

}  // namespace pineda::raster
