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

// GL 1.5 table 6.17: S's object and eye planes start as (1, 0, 0, 0), T's as (0, 1, 0, 0),
// R's and Q's as 0. The eye planes were given under the identity modelview, whose inverse
// leaves them as they are.
inline std::array<TexGenCoordState, 4> initial_texgen_coords() {
  std::array<TexGenCoordState, 4> c{};
  c[0].object_plane = c[0].eye_plane = glm::dvec4(1, 0, 0, 0);
  c[1].object_plane = c[1].eye_plane = glm::dvec4(0, 1, 0, 0);
  return c;
}

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
  std::array<std::array<TexGenCoordState, 4>, raster::kMaxTextureUnits> texgen = [] {
    std::array<std::array<TexGenCoordState, 4>, raster::kMaxTextureUnits> t;
    t.fill(initial_texgen_coords());
    return t;
  }();
};

}  // namespace pineda
