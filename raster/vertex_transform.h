// The fixed-function vertex stage: transform to clip space, lighting, texture matrices.
#pragma once
#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "raster/point_size.h"
#include "raster/texgen.h"
#include "raster/texture.h"
#include "raster/vertex.h"

namespace pineda::raster {

constexpr int kMaxLights = 8;

struct Light {
  bool enabled = false;
  glm::vec4 ambient{0, 0, 0, 1}, diffuse{0, 0, 0, 1}, specular{0, 0, 0, 1};
  glm::vec4 position{0, 0, 1, 0};  // eye coordinates
  glm::vec3 spot_direction{0, 0, -1};  // eye coordinates
  float spot_exponent = 0.f, spot_cutoff = 180.f;
  float constant_attenuation = 1.f, linear_attenuation = 0.f, quadratic_attenuation = 0.f;
};

struct Material {
  glm::vec4 ambient{0.2f, 0.2f, 0.2f, 1}, diffuse{0.8f, 0.8f, 0.8f, 1};
  glm::vec4 specular{0, 0, 0, 1}, emission{0, 0, 0, 1};
  float shininess = 0.f;
  glm::vec3 color_indexes{0, 1, 1};  // ambient, diffuse, specular: only reported (RGBA lighting)
};

// Which material colours follow the current colour (glColorMaterial).
struct ColorMaterial {
  bool enabled = false;
  bool front = true, back = true;
  bool ambient = true, diffuse = true, specular = false, emission = false;
};

struct Lighting {
  bool enabled = false;
  std::array<Light, kMaxLights> lights;
  Material front, back;
  ColorMaterial color_material;
  glm::vec4 model_ambient{0.2f, 0.2f, 0.2f, 1};
  bool local_viewer = false;
  bool two_side = false;
  bool separate_specular = false;  // GL_SEPARATE_SPECULAR_COLOR: specular goes to the secondary colour
};

// The per-vertex values the rasterizer's optional stages read.
struct VertexExtras {
  bool color_sum = false;       // ClipVertex::secondary is read
  bool fog = false;             // ClipVertex::fog is read
  bool fog_from_coord = false;  // GL_FOG_COORDINATE: c is the vertex's fog coordinate, else |z_eye|
  uint32_t clip_planes = 0;     // bit i: ClipVertex::clip_distance[i] is read
  std::array<glm::vec4, kMaxClipPlanes> clip_plane_eye{};  // eye coordinates
  std::array<TexGen, kMaxTextureUnits> texgen;
  bool point_attenuation = false;  // ClipVertex::point_size is read
  PointParameters point;
  float point_size = 1.f;  // glPointSize
};

struct Transform {
  glm::mat4 modelview{1.f};
  glm::mat4 modelview_projection{1.f};
  glm::mat3 normal_matrix{1.f};  // inverse transpose of the modelview's upper 3x3
  bool normalize = false;
  float rescale_factor = 1.f;  // GL_RESCALE_NORMAL's factor, 1 when disabled
  int texture_units = 0;       // units whose coordinates the rasterizer reads
  std::array<glm::mat4, kMaxTextureUnits> texture_matrix;
  std::array<bool, kMaxTextureUnits> texture_matrix_identity{true, true, true, true};
  Lighting lighting;
  VertexExtras extras;
};

void transform_vertices(const Transform& transform, std::span<const VertexInput> in,
                        std::vector<ClipVertex>& out);
// As above, into out[0, in.size()) (out is at least as long as in).
void transform_vertices(const Transform& transform, std::span<const VertexInput> in, std::span<ClipVertex> out);

}  // namespace pineda::raster
