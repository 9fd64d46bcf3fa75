// Vertices before and after the vertex stage.
#pragma once
#include <cstdint>

#include "raster/texture.h"

namespace pineda::raster {

constexpr int kMaxClipPlanes = 6;

// One vertex as the application specified it (immediate mode or client arrays).
struct VertexInput {
  float position[4] = {0, 0, 0, 1};
  float color[4] = {1, 1, 1, 1};
  float normal[3] = {0, 0, 1};
  float texcoord[kMaxTextureUnits][4] = {};
  float secondary_color[3] = {0, 0, 0};
  float fog_coord = 0.f;
  float point_size = 1.f;  // read when PointParameters::size_per_vertex (OES_point_size_array)
  bool edge_flag = true;
  // The array element or immediate-mode slot the vertex came from: state/ reads the generic
  // attributes of programmable draws through it (UINT32_MAX: none).
  uint32_t source = UINT32_MAX;
};

// One vertex after transform and lighting: clip-space position plus the varyings the
// rasterizer interpolates. Colours are clamped to [0, 1]; `back_color` is used for
// back-facing polygons when two-sided lighting is on (equal to `color` otherwise).
// What a programmable draw uses comes first, in 48 bytes: its varyings live in an array of
// their own, and the vertex shader writes only these fields of each vertex.
struct ClipVertex {
  float clip[4];
  // Eye-space distance to each enabled user clip plane (>= 0 is inside).
  float clip_distance[kMaxClipPlanes] = {};
  float point_size = 1.f;  // the derived size, when the point size is attenuated
  bool edge_flag;
  // The fixed-function varyings.
  float color[4];
  float back_color[4];
  float texcoord[kMaxTextureUnits][4];
  // Added to the textured colour when the colour sum is on (secondary colour or separate specular).
  float secondary[3] = {0, 0, 0};
  float back_secondary[3] = {0, 0, 0};
  float fog = 0.f;  // the fog coordinate c: |z_eye| or the vertex's fog coordinate
};

}  // namespace pineda::raster
