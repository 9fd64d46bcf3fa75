#include "state/programs/builtin_uniforms.h"

#include <charconv>
#include <cmath>
#include <string_view>

#include <glm/gtc/matrix_inverse.hpp>

#include "state/context.h"

namespace pineda {
namespace {

// A built-in uniform name split as base[index].member ("gl_LightSource[2].diffuse").
struct BuiltinName {
  std::string_view base, member;
  int index = 0;
  bool indexed = false;
};

BuiltinName split(std::string_view name) {
  BuiltinName n;
  const size_t dot = name.find('.');
  if (dot != std::string_view::npos) {
    n.member = name.substr(dot + 1);
    name = name.substr(0, dot);
  }
  const size_t open = name.find('[');
  if (open != std::string_view::npos && name.back() == ']') {
    std::from_chars(name.data() + open + 1, name.data() + name.size() - 1, n.index);
    n.indexed = true;
    name = name.substr(0, open);
  }
  n.base = name;
  return n;
}

// Writes uniform values: vectors, and matrices column by column (rows floats per column).
struct Writer {
  float* out;
  int components;
  void vec(const glm::vec4& v, int n = 4) const {
    for (int i = 0; i < std::min(n, components); ++i) out[i] = v[i];
  }
  void scalar(float v) const {
    if (components >= 1) out[0] = v;
  }
  void mat4(const glm::mat4& m) const {
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (c * 4 + r < components) out[c * 4 + r] = m[c][r];
  }
  void mat3(const glm::mat3& m) const {
    for (int c = 0; c < 3; ++c)
      for (int r = 0; r < 3; ++r)
        if (c * 3 + r < components) out[c * 3 + r] = m[c][r];
  }
};

bool matrix_value(const Context& ctx, std::string_view base, int index, glm::mat4& out) {
  auto variant = [&](std::string_view prefix, const glm::dmat4& m) -> bool {
    const std::string_view rest = base.substr(prefix.size());
    if (rest.empty()) out = glm::mat4(m);
    else if (rest == "Inverse") out = glm::mat4(glm::inverse(m));
    else if (rest == "Transpose") out = glm::mat4(glm::transpose(m));
    else if (rest == "InverseTranspose") out = glm::mat4(glm::transpose(glm::inverse(m)));
    else return false;
    return true;
  };
  const glm::dmat4& mv = ctx.modelview.top();
  const glm::dmat4& proj = ctx.projection.top();
  if (base.starts_with("gl_ModelViewProjectionMatrix")) return variant("gl_ModelViewProjectionMatrix", proj * mv);
  if (base.starts_with("gl_ModelViewMatrix")) return variant("gl_ModelViewMatrix", mv);
  if (base.starts_with("gl_ProjectionMatrix")) return variant("gl_ProjectionMatrix", proj);
  if (base.starts_with("gl_TextureMatrix")) {
    if (index < 0 || index >= raster::kMaxTextureUnits) return false;
    return variant("gl_TextureMatrix", ctx.texture_matrix[index].top());
  }
  return false;
}

glm::vec4 light_source_member(const raster::Light& l, std::string_view m, bool& ok) {
  ok = true;
  if (m == "ambient") return l.ambient;
  if (m == "diffuse") return l.diffuse;
  if (m == "specular") return l.specular;
  if (m == "position") return l.position;
  if (m == "halfVector") {
    // The half vector of an infinite viewer: normalize(light direction + (0, 0, 1)).
    glm::vec3 dir = glm::vec3(l.position);
    if (l.position.w != 0.f) dir = dir / l.position.w;
    const float len = glm::length(dir);
    if (len > 0.f) dir /= len;
    glm::vec3 h = dir + glm::vec3(0, 0, 1);
    const float hl = glm::length(h);
    if (hl > 0.f) h /= hl;
    return glm::vec4(h, 1.f);
  }
  if (m == "spotDirection") return glm::vec4(l.spot_direction, 0.f);
  if (m == "spotExponent") return glm::vec4(l.spot_exponent);
  if (m == "spotCutoff") return glm::vec4(l.spot_cutoff);
  if (m == "spotCosCutoff") return glm::vec4(std::cos(glm::radians(l.spot_cutoff)));
  if (m == "constantAttenuation") return glm::vec4(l.constant_attenuation);
  if (m == "linearAttenuation") return glm::vec4(l.linear_attenuation);
  if (m == "quadraticAttenuation") return glm::vec4(l.quadratic_attenuation);
  ok = false;
  return {};
}

glm::vec4 material_member(const raster::Material& mat, std::string_view m, bool& ok) {
  ok = true;
  if (m == "emission") return mat.emission;
  if (m == "ambient") return mat.ambient;
  if (m == "diffuse") return mat.diffuse;
  if (m == "specular") return mat.specular;
  if (m == "shininess") return glm::vec4(mat.shininess);
  ok = false;
  return {};
}

// Values of the non-matrix built-ins; false for a name Pineda does not know.
bool state_value(const Context& ctx, const BuiltinName& n, const Writer& w) {
  const raster::Lighting& lt = ctx.lighting;
  bool ok = false;
  if (n.base == "gl_LightSource") {
    if (n.index < 0 || n.index >= raster::kMaxLights) return false;
    const glm::vec4 v = light_source_member(lt.lights[n.index], n.member, ok);
    if (ok) w.vec(v);
    return ok;
  }
  if (n.base == "gl_FrontMaterial" || n.base == "gl_BackMaterial") {
    const glm::vec4 v = material_member(n.base == "gl_FrontMaterial" ? lt.front : lt.back, n.member, ok);
    if (ok) w.vec(v);
    return ok;
  }
  if (n.base == "gl_LightModel" && n.member == "ambient") return w.vec(lt.model_ambient), true;
  if ((n.base == "gl_FrontLightModelProduct" || n.base == "gl_BackLightModelProduct") && n.member == "sceneColor") {
    const raster::Material& m = n.base == "gl_FrontLightModelProduct" ? lt.front : lt.back;
    // Alpha is the material's diffuse alpha, the alpha lighting produces (GL 2.0 2.14.1), as
    // Mesa (piglit glsl-1.10-built-in-uniform-state checks it).
    glm::vec4 scene = m.emission + m.ambient * lt.model_ambient;
    scene.a = m.diffuse.a;
    w.vec(scene);
    return true;
  }
  if (n.base == "gl_FrontLightProduct" || n.base == "gl_BackLightProduct") {
    if (n.index < 0 || n.index >= raster::kMaxLights) return false;
    const raster::Material& m = n.base == "gl_FrontLightProduct" ? lt.front : lt.back;
    const raster::Light& l = lt.lights[n.index];
    // Colour products with the material's alpha, as Mesa and NVIDIA do.
    auto product = [](const glm::vec4& light, const glm::vec4& material) {
      return glm::vec4(glm::vec3(light) * glm::vec3(material), material.a);
    };
    if (n.member == "ambient") return w.vec(product(l.ambient, m.ambient)), true;
    if (n.member == "diffuse") return w.vec(product(l.diffuse, m.diffuse)), true;
    if (n.member == "specular") return w.vec(product(l.specular, m.specular)), true;
    return false;
  }
  if (n.base == "gl_Fog") {
    const raster::Fog& f = ctx.draw_state.fog;
    if (n.member == "color") return w.vec(glm::vec4(f.color[0], f.color[1], f.color[2], f.color[3])), true;
    if (n.member == "density") return w.scalar(f.density), true;
    if (n.member == "start") return w.scalar(f.start), true;
    if (n.member == "end") return w.scalar(f.end), true;
    if (n.member == "scale") return w.scalar(f.end != f.start ? 1.f / (f.end - f.start) : 0.f), true;
    return false;
  }
  if (n.base == "gl_Point") {
    const raster::PointParameters& p = ctx.draw_state.point_params;
    if (n.member == "size") return w.scalar(ctx.draw_state.point_size), true;
    if (n.member == "sizeMin") return w.scalar(p.size_min), true;
    if (n.member == "sizeMax") return w.scalar(p.size_max), true;
    if (n.member == "fadeThresholdSize") return w.scalar(p.fade_threshold), true;
    if (n.member == "distanceConstantAttenuation") return w.scalar(p.attenuation[0]), true;
    if (n.member == "distanceLinearAttenuation") return w.scalar(p.attenuation[1]), true;
    if (n.member == "distanceQuadraticAttenuation") return w.scalar(p.attenuation[2]), true;
    return false;
  }
  if (n.base == "gl_DepthRange") {
    const raster::Viewport& v = ctx.viewport;
    if (n.member == "near") return w.scalar(static_cast<float>(v.near_z)), true;
    if (n.member == "far") return w.scalar(static_cast<float>(v.far_z)), true;
    if (n.member == "diff") return w.scalar(static_cast<float>(v.far_z - v.near_z)), true;
    return false;
  }
  if (n.base == "gl_ClipPlane") {
    if (n.index < 0 || n.index >= raster::kMaxClipPlanes) return false;
    return w.vec(glm::vec4(ctx.extras.clip_planes[n.index])), true;
  }
  if (n.base == "gl_TextureEnvColor") {
    if (n.index < 0 || n.index >= raster::kMaxTextureUnits) return false;
    const float* c = ctx.texture_units[n.index].env.color;
    return w.vec(glm::vec4(c[0], c[1], c[2], c[3])), true;
  }
  static constexpr std::string_view kPlanes[8] = {"gl_EyePlaneS", "gl_EyePlaneT", "gl_EyePlaneR", "gl_EyePlaneQ",
                                                  "gl_ObjectPlaneS", "gl_ObjectPlaneT", "gl_ObjectPlaneR", "gl_ObjectPlaneQ"};
  for (int i = 0; i < 8; ++i) {
    if (n.base != kPlanes[i]) continue;
    if (n.index < 0 || n.index >= raster::kMaxTextureUnits) return false;
    const TexGenCoordState& c = ctx.extras.texgen[n.index][i % 4];
    return w.vec(glm::vec4(i < 4 ? c.eye_plane : c.object_plane)), true;
  }
  if (n.base == "gl_NormalMatrix") {
    w.mat3(glm::mat3(glm::inverseTranspose(glm::dmat3(ctx.modelview.top()))));
    return true;
  }
  if (n.base == "gl_NormalScale") {
    const glm::dmat3 inv = glm::inverse(glm::dmat3(ctx.modelview.top()));
    const double len = glm::length(glm::dvec3(inv[0][2], inv[1][2], inv[2][2]));
    w.scalar(ctx.rescale_normal && len > 0.0 ? static_cast<float>(1.0 / len) : 1.f);
    return true;
  }
  return false;
}

}  // namespace

void fill_builtin_uniforms(const Context& ctx, const shader::Program& program, std::vector<float>& values) {
  for (const shader::Uniform& u : program.uniforms()) {
    if (!u.builtin) continue;
    BuiltinName n = split(u.name);
    const int elements = std::max(u.array_size, 1);
    const int components = u.type.components();
    for (int e = 0; e < elements; ++e) {
      const size_t at = static_cast<size_t>(u.offset + e * u.stride);
      if (u.offset < 0 || at + static_cast<size_t>(components) > values.size()) break;
      BuiltinName element = n;
      if (elements > 1 || (n.indexed && n.member.empty())) element.index = n.index + e;
      const Writer w{values.data() + at, components};
      glm::mat4 m;
      if (matrix_value(ctx, element.base, element.index, m)) w.mat4(m);
      else state_value(ctx, element, w);
    }
  }
}

}  // namespace pineda
