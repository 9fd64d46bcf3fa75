// Client images for texture tests.
#pragma once
#include <cstdint>
#include <vector>

#include <GL/glext.h>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {

// `texels` RGBA8 texels of one colour.
inline std::vector<uint8_t> solid_texels(int texels, const Rgba& c) {
  std::vector<uint8_t> t;
  for (int i = 0; i < texels; ++i)
    for (int v : c) t.push_back(uint8_t(v));
  return t;
}

// A 4x4 RGBA8 image whose texel (s, t) is grid_texel(s, t): every texel differs.
inline Rgba grid_texel(int s, int t) { return {40 * s + 10, 40 * t + 10, 200, 255}; }
inline std::vector<uint8_t> grid_texels() {
  std::vector<uint8_t> out;
  for (int t = 0; t < 4; ++t)
    for (int s = 0; s < 4; ++s)
      for (int c : grid_texel(s, t)) out.push_back(uint8_t(c));
  return out;
}

// A kRectWidth x kRectHeight image (not powers of two) whose texels all differ, for rectangle
// textures: texel (i, j) is rect_texel(i, j).
constexpr int kRectWidth = 5, kRectHeight = 3;
inline Rgba rect_texel(int i, int j) { return {40 * i + 20, 60 * j + 30, 200 - 30 * i, 255}; }

// Loads that image into the rectangle texture bound to the active unit.
inline void load_rect_image() {
  std::vector<uint8_t> data;
  for (int j = 0; j < kRectHeight; ++j)
    for (int i = 0; i < kRectWidth; ++i)
      for (int c : rect_texel(i, j)) data.push_back(uint8_t(c));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGBA, kRectWidth, kRectHeight, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               data.data());
}

}  // namespace pineda::test
