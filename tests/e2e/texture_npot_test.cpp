// ARB_texture_non_power_of_two (GL 2.0 core): textures of any size, with every wrap mode and
// filter, mipmap chains of halved sizes rounded down (GL 2.0 3.8.10), generated mipmaps, and
// 1D, 3D and cube map targets. Exact texels.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/texel_images.h"

namespace pineda::test {
namespace {

Rgba texel(int i, int j) { return {30 + 40 * i, 20 + 20 * j, 9, 255}; }

std::vector<uint8_t> named_texels(int w, int h) {
  std::vector<uint8_t> t;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int c : texel(i, j)) t.push_back(uint8_t(c));
  return t;
}

class TextureNpotTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }
  // A window-aligned rectangle with texture coordinates (s0, t0) .. (s1, t1), r fixed.
  static void rect(int x0, int y0, int x1, int y1, float s0, float t0, float s1, float t1, float r = 0.f) {
    glBegin(GL_QUADS);
    glTexCoord3f(s0, t0, r);
    glVertex2i(x0, y0);
    glTexCoord3f(s1, t0, r);
    glVertex2i(x1, y0);
    glTexCoord3f(s1, t1, r);
    glVertex2i(x1, y1);
    glTexCoord3f(s0, t1, r);
    glVertex2i(x0, y1);
    glEnd();
  }
  static void nearest(GLenum target) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
};

TEST_F(TextureNpotTest, Advertised) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_ARB_texture_non_power_of_two "), std::string::npos);
}

TEST_F(TextureNpotTest, TwoDimensionalTexelsRepeat) {
  const std::vector<uint8_t> t = named_texels(3, 5);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 3, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  nearest(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_2D);
  rect(0, 0, 6, 10, 0.f, 0.f, 2.f, 2.f);  // two repeats each way: one texel per pixel
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 6; ++x) EXPECT_TRUE(near_rgba(pixel(x, y), texel(x % 3, y % 5))) << x << "," << y;
}

TEST_F(TextureNpotTest, MirroredRepeatAndClampToEdge) {
  const std::vector<uint8_t> t = named_texels(3, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 3, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  nearest(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  rect(0, 0, 6, 1, 0.f, 0.5f, 2.f, 0.5f);
  const int mirrored[6] = {0, 1, 2, 2, 1, 0};
  for (int x = 0; x < 6; ++x) EXPECT_TRUE(near_rgba(pixel(x, 0), texel(mirrored[x], 0))) << x;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  rect(0, 1, 6, 2, 0.f, 0.5f, 2.f, 0.5f);
  const int clamped[6] = {0, 1, 2, 2, 2, 2};
  for (int x = 0; x < 6; ++x) EXPECT_TRUE(near_rgba(pixel(x, 1), texel(clamped[x], 0))) << x;
}

TEST_F(TextureNpotTest, LinearFilterWrapsAcrossTheNpotEdge) {
  // Texels 0, 120, 240 in red; pixel centres on texel edges blend neighbours half and half,
  // and the first blends the last texel with the first (REPEAT).
  const uint8_t t[] = {0, 0, 0, 255, 120, 0, 0, 255, 240, 0, 0, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 3, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glEnable(GL_TEXTURE_2D);
  rect(0, 0, 6, 1, -1.f / 6.f, 0.5f, 2.f - 1.f / 6.f, 0.5f);  // pixel x's centre at s = x / 3
  const int expected[6] = {120, 60, 180, 120, 60, 180};
  for (int x = 0; x < 6; ++x) EXPECT_TRUE(near_rgba(pixel(x, 0), {expected[x], 0, 0, 255}, 1)) << x;
}

TEST_F(TextureNpotTest, MipmapChainHalvesRoundingDown) {
  const Rgba red{255, 0, 0, 255}, green{0, 255, 0, 255}, blue{0, 0, 255, 255};
  const std::vector<uint8_t> l0 = solid_texels(7 * 5, red), l1 = solid_texels(3 * 2, green),
                             l2 = solid_texels(1, blue);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 7, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, l0.data());
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 3, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, l1.data());
  glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, l2.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glColor3f(1, 1, 1);
  rect(0, 0, 7, 5, 0.f, 0.f, 1.f, 1.f);     // one texel per pixel: level 0
  rect(10, 0, 13, 2, 0.f, 0.f, 1.f, 1.f);   // rho = 7/3: lambda 1.2, level 1
  rect(20, 0, 21, 1, 0.f, 0.f, 1.f, 1.f);   // rho = 7: level 2
  EXPECT_EQ(count_pixels(red), 35);
  EXPECT_EQ(count_pixels(green), 6);
  EXPECT_EQ(count_pixels(blue), 1);
  // Level 1 of 4x2 does not halve 7x5 (3x2 does): the texture is incomplete, texturing is off.
  const std::vector<uint8_t> wrong = solid_texels(4 * 2, green);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA8, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, wrong.data());
  clear_to(0, 0, 0, 0);
  rect(0, 0, 7, 5, 0.f, 0.f, 1.f, 1.f);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 35);
}

TEST_F(TextureNpotTest, GeneratedMipmapsOfAnNpotImage) {
  glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
  const std::vector<uint8_t> t = solid_texels(5 * 3, {10, 200, 30, 255});
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  const int sizes[3][2] = {{5, 3}, {2, 1}, {1, 1}};
  for (int level = 0; level < 3; ++level) {
    GLint w = 0, h = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &h);
    EXPECT_EQ(w, sizes[level][0]) << level;
    EXPECT_EQ(h, sizes[level][1]) << level;
  }
  uint8_t level2[4] = {};
  glGetTexImage(GL_TEXTURE_2D, 2, GL_RGBA, GL_UNSIGNED_BYTE, level2);
  EXPECT_TRUE(near_rgba({level2[0], level2[1], level2[2], level2[3]}, {10, 200, 30, 255}));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glEnable(GL_TEXTURE_2D);
  rect(0, 0, 1, 1, 0.f, 0.f, 1.f, 1.f);  // level 2
  EXPECT_TRUE(near_rgba(pixel(0, 0), {10, 200, 30, 255}));
}

TEST_F(TextureNpotTest, OneDimensional) {
  const std::vector<uint8_t> t = named_texels(5, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA8, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  nearest(GL_TEXTURE_1D);
  glEnable(GL_TEXTURE_1D);
  rect(0, 0, 10, 1, 0.f, 0.f, 2.f, 1.f);
  for (int x = 0; x < 10; ++x) EXPECT_TRUE(near_rgba(pixel(x, 0), texel(x % 5, 0))) << x;
}

TEST_F(TextureNpotTest, ThreeDimensional) {
  // 3x2x5: slice k holds texel(i, j + 2 k).
  std::vector<uint8_t> t;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        for (int c : texel(i, j + 2 * k)) t.push_back(uint8_t(c));
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 3, 2, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  nearest(GL_TEXTURE_3D);
  glEnable(GL_TEXTURE_3D);
  rect(0, 0, 3, 2, 0.f, 0.f, 1.f, 1.f, 3.5f / 5.f);  // slice 3
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) EXPECT_TRUE(near_rgba(pixel(x, y), texel(x, y + 6))) << x << "," << y;
}

TEST_F(TextureNpotTest, CubeMapFaces) {
  const GLenum faces[] = {GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_CUBE_MAP_NEGATIVE_X,
                          GL_TEXTURE_CUBE_MAP_POSITIVE_Y, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y,
                          GL_TEXTURE_CUBE_MAP_POSITIVE_Z, GL_TEXTURE_CUBE_MAP_NEGATIVE_Z};
  for (int f = 0; f < 6; ++f) {
    const std::vector<uint8_t> t = solid_texels(5 * 5, {40 * f, 255 - 40 * f, 3, 255});
    glTexImage2D(faces[f], 0, GL_RGBA8, 5, 5, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  }
  nearest(GL_TEXTURE_CUBE_MAP);
  glEnable(GL_TEXTURE_CUBE_MAP);
  // Direction +Z (face 4) and -X (face 1).
  rect(0, 0, 2, 2, 0.f, 0.f, 0.f, 0.f, 1.f);
  glBegin(GL_QUADS);
  glTexCoord3f(-1.f, 0.f, 0.f);
  glVertex2i(4, 0);
  glVertex2i(6, 0);
  glVertex2i(6, 2);
  glVertex2i(4, 2);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(1, 1), {160, 95, 3, 255}));
  EXPECT_TRUE(near_rgba(pixel(5, 1), {40, 215, 3, 255}));
}

}  // namespace
}  // namespace pineda::test
