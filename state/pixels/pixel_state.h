// The state of raster position and pixel rectangles (GL 1.5 spec 2.13, 3.6, 3.7): the
// current raster position, the pixel-transfer modes and the pixel maps.
#pragma once
#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "raster/texture.h"

namespace pineda {

// An integer parameter given as a float (glPixelStoref, glPixelTransferf): rounded to the
// nearest integer whatever the FPU rounding mode, clamped to GLint; NaN is 0.
inline GLint round_int_param(double v) {
  return std::isnan(v) ? 0 : static_cast<GLint>(std::clamp(std::round(v), -2147483648.0, 2147483647.0));
}

// The same truncated toward zero, as C converts (glCallLists' GL_FLOAT names, integer
// queries of float state); a value beyond GLint is clamped instead of undefined.
inline GLint truncate_int_param(double v) {
  return std::isnan(v) ? 0 : static_cast<GLint>(std::clamp(v, -2147483648.0, 2147483647.0));
}

// A colour component in an integer query (GL 1.1 6.1.2): [-1, 1] maps linearly onto the GLint
// range, beyond is clamped, NaN is 0.
inline GLint colour_int_param(double v) {
  return std::isnan(v) ? 0 : static_cast<GLint>(std::clamp(v, -1.0, 1.0) * 2147483647.0);
}

// The reverse, for a colour given as integers (glLightiv, glTexEnviv, glTexParameteriv...):
// the GLint range maps linearly onto [-1, 1] (GL 1.1 2.13 table 2.6).
inline GLfloat colour_from_int_param(GLint v) { return static_cast<GLfloat>((2.0 * v + 1.0) / 4294967295.0); }

// GL_CURRENT_RASTER_*: saved with GL_CURRENT_BIT.
struct RasterPosition {
  float window[4] = {0, 0, 0, 1};  // x, y, z in window coordinates; w is the clip w
  bool valid = true;
  float color[4] = {1, 1, 1, 1};
  float secondary_color[4] = {0, 0, 0, 1};  // GL 2.1's CURRENT_RASTER_SECONDARY_COLOR
  float texcoord[raster::kMaxTextureUnits][4] = {{0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}};
  float distance = 0.f;  // from the eye, for fog
};

// glPixelTransfer and glPixelZoom: saved with GL_PIXEL_MODE_BIT.
struct PixelMode {
  bool map_color = false, map_stencil = false;
  GLint index_shift = 0, index_offset = 0;
  float scale[4] = {1, 1, 1, 1}, bias[4] = {0, 0, 0, 0};  // RGBA
  float depth_scale = 1.f, depth_bias = 0.f;
  float zoom_x = 1.f, zoom_y = 1.f;
};

constexpr int kMaxPixelMapTable = 256;
constexpr int kPixelMapCount = GL_PIXEL_MAP_A_TO_A - GL_PIXEL_MAP_I_TO_I + 1;

// glPixelMap tables, indexed by map - GL_PIXEL_MAP_I_TO_I. Colour maps hold [0, 1] values,
// I_TO_I and S_TO_S hold indices. Each starts with one entry, 0.
struct PixelMaps {
  std::array<std::vector<float>, kPixelMapCount> tables;
  PixelMaps() {
    for (auto& t : tables) t.assign(1, 0.f);
  }
  const std::vector<float>& operator[](GLenum map) const { return tables[map - GL_PIXEL_MAP_I_TO_I]; }
  std::vector<float>& operator[](GLenum map) { return tables[map - GL_PIXEL_MAP_I_TO_I]; }
};

}  // namespace pineda
