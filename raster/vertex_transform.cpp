#include "raster/vertex_transform.h"

#include <algorithm>
#include <cmath>
#include <optional>

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

// One batch of up to kVertexLanes vertices through the stage: the lanes between the inputs
// and the outputs, and the steps over them. The lanes' values are the bits the GLM expressions
// of one vertex give (vertex_lanes.h).
class VertexBatch {
 public:
  explicit VertexBatch(const Transform& t)
      : t_(t),
        needs_(needs_of(t)),
        prepared_(t.lighting.enabled ? std::optional(prepare_lights(t.lighting)) : std::nullopt) {
    // Zero where not computed, as each vertex alone would have them (set once: no batch writes
    // them), when lighting or the extras read them: a draw of a few vertices without either
    // spent half of its transform zeroing them.
    if (per_vertex_extras_ || t.lighting.enabled) {
      eye4_ = LaneVec4{};
      normal_ = LaneVec3{};
    }
  }

  void run(const VertexInput* v, ClipVertex* o, int n) {
    v_ = v;
    o_ = o;
    n_ = n;
    if (in_lanes_) {
      clip_positions_in_lanes();
      if (needs_.eye) eye_coordinates();
      if (needs_.normal) eye_normals();
    } else {
      clip_positions();
    }
    if (t_.lighting.enabled) lit_colors();
    else plain_colors();
    if (per_vertex_extras_) extras();
  }

 private:
  // Only the clip position: turning the vertices into lanes and back would cost more than the
  // lanes save. GLM's product, which the lanes reproduce operation by operation.
  void clip_positions() {
    for (int i = 0; i < n_; ++i) {
      const float* p = v_[i].position;
      store(o_[i].clip, t_.modelview_projection * glm::vec4(p[0], p[1], p[2], p[3]));
      o_[i].edge_flag = v_[i].edge_flag;
    }
  }

  // m * (x, y, z, w) as GLM computes it: (m0 x + m1 y) + (m2 z + m3 w), row `row` of the result.
  void transform(const glm::mat4& m, int row, Lanes& result) const {
    const float a = m[0][row], b = m[1][row], c = m[2][row], d = m[3][row];
    for (int i = 0; i < n_; ++i) result[i] = (a * obj_.x[i] + b * obj_.y[i]) + (c * obj_.z[i] + d * obj_.w[i]);
  }

  void clip_positions_in_lanes() {
    for (int i = 0; i < n_; ++i) {
      obj_.x[i] = v_[i].position[0];
      obj_.y[i] = v_[i].position[1];
      obj_.z[i] = v_[i].position[2];
      obj_.w[i] = v_[i].position[3];
    }
    LaneVec4 clip;
    transform(t_.modelview_projection, 0, clip.x);
    transform(t_.modelview_projection, 1, clip.y);
    transform(t_.modelview_projection, 2, clip.z);
    transform(t_.modelview_projection, 3, clip.w);
    for (int i = 0; i < n_; ++i) {
      o_[i].clip[0] = clip.x[i];
      o_[i].clip[1] = clip.y[i];
      o_[i].clip[2] = clip.z[i];
      o_[i].clip[3] = clip.w[i];
      o_[i].edge_flag = v_[i].edge_flag;
    }
  }

  void eye_coordinates() {
    transform(t_.modelview, 0, eye4_.x);
    transform(t_.modelview, 1, eye4_.y);
    transform(t_.modelview, 2, eye4_.z);
    transform(t_.modelview, 3, eye4_.w);
  }

  // The normal matrix times the normal, rescaled, normalized with GL_NORMALIZE.
  void eye_normals() {
    const glm::mat3 m = t_.normal_matrix;  // copies: the loop's stores cannot change them
    const float r = t_.rescale_factor;
    const bool normalize = t_.normalize;
    LaneVec3 in;
    for (int i = 0; i < n_; ++i) {
      in.x[i] = v_[i].normal[0];
      in.y[i] = v_[i].normal[1];
      in.z[i] = v_[i].normal[2];
    }
    for (int i = 0; i < n_; ++i) {
      const float nx = in.x[i], ny = in.y[i], nz = in.z[i];
      float a = (m[0][0] * nx + m[1][0] * ny) + m[2][0] * nz;
      float b = (m[0][1] * nx + m[1][1] * ny) + m[2][1] * nz;
      float c = (m[0][2] * nx + m[1][2] * ny) + m[2][2] * nz;
      a *= r;
      b *= r;
      c *= r;
      if (normalize) {  // a select, so that the loop vectorizes: x / 1 is x
        const float len = std::sqrt(a * a + b * b + c * c);
        const float divisor = len > 0.f ? len : 1.f;
        a /= divisor;
        b /= divisor;
        c /= divisor;
      }
      normal_.x[i] = a;
      normal_.y[i] = b;
      normal_.z[i] = c;
    }
  }

  void store_lit(float (ClipVertex::*rgba)[4], float (ClipVertex::*rgb)[3]) {
    for (int i = 0; i < n_; ++i) {
      float* c = o_[i].*rgba;
      c[0] = color_.x[i];
      c[1] = color_.y[i];
      c[2] = color_.z[i];
      c[3] = color_.w[i];
      float* s = o_[i].*rgb;
      s[0] = specular_.x[i];
      s[1] = specular_.y[i];
      s[2] = specular_.z[i];
    }
  }

  void lit_colors() {
    const Lighting& lighting = t_.lighting;
    for (int i = 0; i < n_; ++i) {
      const float w = eye4_.w[i];
      const bool divide = w != 0.f;
      eye_pos_.x[i] = divide ? eye4_.x[i] / w : eye4_.x[i];
      eye_pos_.y[i] = divide ? eye4_.y[i] / w : eye4_.y[i];
      eye_pos_.z[i] = divide ? eye4_.z[i] / w : eye4_.z[i];
    }
    for (int i = 0; i < n_; ++i) colors_[i] = v_[i].color;
    lane_material(lighting, true, colors_, n_, material_);
    light_lanes(lighting, *prepared_, material_, eye_pos_, normal_, n_, color_, specular_);
    store_lit(&ClipVertex::color, &ClipVertex::secondary);
    if (lighting.two_side) {
      LaneVec3 back_normal;
      for (int i = 0; i < n_; ++i) {
        back_normal.x[i] = -normal_.x[i];
        back_normal.y[i] = -normal_.y[i];
        back_normal.z[i] = -normal_.z[i];
      }
      lane_material(lighting, false, colors_, n_, material_);
      light_lanes(lighting, *prepared_, material_, eye_pos_, back_normal, n_, color_, specular_);
      store_lit(&ClipVertex::back_color, &ClipVertex::back_secondary);
    } else {
      for (int i = 0; i < n_; ++i) {
        std::copy(o_[i].color, o_[i].color + 4, o_[i].back_color);
        std::copy(o_[i].secondary, o_[i].secondary + 3, o_[i].back_secondary);
      }
    }
  }

  void plain_colors() {
    for (int i = 0; i < n_; ++i) {
      for (int c = 0; c < 4; ++c) o_[i].color[c] = o_[i].back_color[c] = std::clamp(v_[i].color[c], 0.f, 1.f);
      if (t_.extras.color_sum)
        for (int c = 0; c < 3; ++c)
          o_[i].secondary[c] = o_[i].back_secondary[c] = std::clamp(v_[i].secondary_color[c], 0.f, 1.f);
    }
  }

  // Fog coordinates, point sizes, clip distances and texture coordinates, vertex by vertex.
  void extras() {
    const VertexExtras& x = t_.extras;
    for (int i = 0; i < n_; ++i) {
      const VertexInput& v = v_[i];
      ClipVertex& o = o_[i];
      const glm::vec4 eye(eye4_.x[i], eye4_.y[i], eye4_.z[i], eye4_.w[i]);
      if (x.fog) o.fog = std::fabs(x.fog_from_coord ? v.fog_coord : eye.z);
      if (x.point_attenuation)
        o.point_size = derived_point_size(x.point, x.point.size_per_vertex ? v.point_size : x.point_size, std::fabs(eye.z));
      for (uint32_t planes = x.clip_planes; planes; planes &= planes - 1) {
        const int p = __builtin_ctz(planes);
        o.clip_distance[p] = glm::dot(x.clip_plane_eye[p], eye);
      }
      for (int u = 0; u < t_.texture_units; ++u) {
        float coords[4] = {v.texcoord[u][0], v.texcoord[u][1], v.texcoord[u][2], v.texcoord[u][3]};
        if (needs_.texgen && x.texgen[u].any()) {
          const glm::vec4 position(obj_.x[i], obj_.y[i], obj_.z[i], obj_.w[i]);
          const glm::vec3 normal(normal_.x[i], normal_.y[i], normal_.z[i]);
          generate_texcoords(x.texgen[u], {position, eye, normal}, coords);
        }
        const glm::vec4 tc(coords[0], coords[1], coords[2], coords[3]);
        store(o.texcoord[u], t_.texture_matrix_identity[u] ? tc : t_.texture_matrix[u] * tc);
      }
    }
  }

  const Transform& t_;
  const Needs needs_;
  // With lighting only: zeroing the lights of a draw without it was most of a one-triangle
  // draw's transform.
  const std::optional<PreparedLights> prepared_;
  const bool in_lanes_ = needs_.eye || needs_.normal;  // positions in lanes (else only clip positions)
  const bool per_vertex_extras_ =
      t_.extras.fog || t_.extras.point_attenuation || t_.extras.clip_planes != 0 || t_.texture_units > 0;
  const VertexInput* v_ = nullptr;
  ClipVertex* o_ = nullptr;
  int n_ = 0;
  LaneVec4 obj_;
  LaneVec4 eye4_;  // (zero where not computed: the constructor)
  LaneVec3 normal_, eye_pos_;
  LaneMaterial material_;
  LaneVec4 color_;
  LaneVec3 specular_;
  const float* colors_[kVertexLanes];
};

}  // namespace

void transform_vertices(const Transform& t, std::span<const VertexInput> in, std::vector<ClipVertex>& out) {
  out.resize(in.size());
  transform_vertices(t, in, std::span<ClipVertex>(out));
}

void transform_vertices(const Transform& t, std::span<const VertexInput> in, std::span<ClipVertex> out) {
  VertexBatch batch(t);
  for (size_t base = 0; base < in.size(); base += kVertexLanes)
    batch.run(&in[base], &out[base], static_cast<int>(std::min<size_t>(kVertexLanes, in.size() - base)));
}

}  // namespace pineda::raster
