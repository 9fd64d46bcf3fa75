// GL state of fog, user clip planes, texture coordinate generation, line and polygon stipple
// and the secondary colour, as the API reports it. What the rasterizer reads lives in
// Context::draw_state (fog, stipple, clip plane enables) and is built per draw.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <array>

#include <glm/glm.hpp>

#include "raster/texture.h"
#include "raster/vertex.h"

namespace pineda {

struct TexGenCoordState {
  bool enabled = false;
  GLenum mode = GL_EYE_LINEAR;
  glm::dvec4 object_plane{0, 0, 0, 0};
  glm::dvec4 eye_plane{0, 0, 0, 0};  // as stored: multiplied by the inverse modelview
};

struct VertexExtrasState {
  // Fog (its rendering values are in draw_state.fog)
  GLenum fog_mode = GL_EXP;
  GLenum fog_coord_source = GL_FRAGMENT_DEPTH;
  float fog_index = 0.f;
  float current_fog_coord = 0.f;

  // Secondary colour and the colour sum
  float current_secondary_color[4] = {0, 0, 0, 1};
  bool color_sum = false;  // GL_COLOR_SUM

  // User clip planes in eye coordinates (enables: draw_state.clip_planes)
  std::array<glm::dvec4, raster::kMaxClipPlanes> clip_planes{};
  std::array<bool, raster::kMaxClipPlanes> clip_plane_enabled{};

  // Texture coordinate generation, per texture unit: s, t, r, q
  std::array<std::array<TexGenCoordState, 4>, raster::kMaxTextureUnits> texgen{};
};

}  // namespace pineda
