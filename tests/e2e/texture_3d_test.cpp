// 3D textures (GL 1.2): slices chosen by r, every R wrap mode, the mip level chosen by the
// r derivative too, trilinear blending, IMAGE_HEIGHT/SKIP_IMAGES, sub-images, copies,
// generated mipmaps, display lists, enable priority and the error codes.
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/texel_images.h"

namespace pineda::test {
namespace {

// Texel (x, y, z) of an n x n x n texture: (40 x + 10, 40 y + 10, 40 z + 10, 255).
Rgba cube_texel(int x, int y, int z) { return {40 * x + 10, 40 * y + 10, 40 * z + 10, 255}; }

std::vector<uint8_t> cube_texels(int n) {
  std::vector<uint8_t> t;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        for (int c : cube_texel(x, y, z)) t.push_back(uint8_t(c));
  return t;
}

class Texture3DTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glBindTexture(GL_TEXTURE_3D, 1);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  }
  void load_cube(int n) {
    const std::vector<uint8_t> texels = cube_texels(n);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, n, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  // A rectangle with s, t across it and r varying from r0 (left) to r1 (right).
  void rect(float x0, float y0, float x1, float y1, float s0, float t0, float s1, float t1, float r0, float r1) {
    glBegin(GL_QUADS);
    glTexCoord3f(s0, t0, r0);
    glVertex2f(x0, y0);
    glTexCoord3f(s1, t0, r1);
    glVertex2f(x1, y0);
    glTexCoord3f(s1, t1, r1);
    glVertex2f(x1, y1);
    glTexCoord3f(s0, t1, r0);
    glVertex2f(x0, y1);
    glEnd();
  }
};

TEST_F(Texture3DTest, NearestReadsTheSliceThatRSelects) {
  load_cube(4);
  for (int k = 0; k < 4; ++k) {
    const float r = (k + 0.5f) / 4;
    rect(8.f * k, 0, 8.f * k + 4, 4, 0, 0, 1, 1, r, r);  // one pixel per texel
  }
  for (int k = 0; k < 4; ++k)
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < 4; ++x)
        EXPECT_TRUE(near_rgba(pixel(8 * k + x, y), cube_texel(x, y, k))) << k << ": " << x << "," << y;
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Texture3DTest, LinearBlendsNeighbouringSlices) {
  load_cube(4);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  rect(0, 0, 4, 4, 0, 0, 1, 1, 0.25f, 0.25f);  // halfway between the centres of slices 0 and 1
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_TRUE(near_rgba(pixel(x, y), {40 * x + 10, 40 * y + 10, 30, 255}, 1));
}

struct WrapCase {
  GLenum mode;
  GLenum filter;
  float r;
  Rgba expected;  // of a 1x1x4 texture whose slice k is (60 k, 0, 0, 255), border (0, 0, 255, 255)
};

TEST_F(Texture3DTest, EveryRWrapMode) {
  std::vector<uint8_t> texels;
  for (int k = 0; k < 4; ++k)
    for (int c : Rgba{60 * k, 0, 0, 255}) texels.push_back(uint8_t(c));
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  const GLfloat border[4] = {0, 0, 1, 1};
  glTexParameterfv(GL_TEXTURE_3D, GL_TEXTURE_BORDER_COLOR, border);
  const WrapCase cases[] = {
      {GL_REPEAT, GL_NEAREST, 1.375f, {60, 0, 0, 255}},           // 0.375: slice 1
      {GL_REPEAT, GL_NEAREST, -0.125f, {180, 0, 0, 255}},         // 0.875: slice 3
      {GL_CLAMP_TO_EDGE, GL_NEAREST, 1.5f, {180, 0, 0, 255}},
      {GL_CLAMP_TO_EDGE, GL_NEAREST, -0.5f, {0, 0, 0, 255}},
      {GL_CLAMP_TO_EDGE, GL_LINEAR, 1.5f, {180, 0, 0, 255}},      // never the border
      {GL_CLAMP, GL_NEAREST, 1.5f, {180, 0, 0, 255}},
      {GL_CLAMP, GL_LINEAR, 1.5f, {90, 0, 128, 255}},             // half slice 3, half border
      {GL_CLAMP_TO_BORDER, GL_NEAREST, 1.5f, {0, 0, 255, 255}},
      {GL_CLAMP_TO_BORDER, GL_NEAREST, 0.6f, {120, 0, 0, 255}},
      {GL_MIRRORED_REPEAT, GL_NEAREST, 1.125f, {180, 0, 0, 255}},  // mirrored to 0.875
      {GL_MIRRORED_REPEAT, GL_NEAREST, 1.625f, {60, 0, 0, 255}},   // mirrored to 0.375
  };
  int i = 0;
  for (const WrapCase& c : cases) {
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GLint(c.mode));
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GLint(c.filter));
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GLint(c.filter));
    rect(float(2 * i), 0, float(2 * i + 1), 1, 0.5f, 0.5f, 0.5f, 0.5f, c.r, c.r);
    EXPECT_TRUE(near_rgba(pixel(2 * i, 0), c.expected, 1)) << "case " << i;
    ++i;
  }
  GLint mode = 0;
  glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, &mode);
  EXPECT_EQ(mode, GL_MIRRORED_REPEAT);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// An 8x8x8 chain whose levels are red, green, blue and white.
void load_coloured_chain() {
  const Rgba colours[4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
  for (int level = 0, n = 8; level < 4; ++level, n /= 2) {
    const std::vector<uint8_t> t = solid_texels(n * n * n, colours[level]);
    glTexImage3D(GL_TEXTURE_3D, level, GL_RGBA, n, n, n, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  }
}

TEST_F(Texture3DTest, MipLevelFollowsTheLargestDerivativeIncludingR) {
  load_coloured_chain();
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  rect(0, 0, 8, 8, 0, 0, 1, 1, 0, 0);      // one texel per pixel: level 0
  rect(10, 0, 12, 2, 0, 0, 1, 1, 0, 0);    // 4 texels per pixel in s and t: level 2
  rect(20, 0, 28, 8, 0, 0, 1, 1, 0, 2);    // s, t one texel per pixel, r 2 texels per pixel: level 1
  rect(0, 10, 8, 18, 0, 0, 1, 1, 0, 8);    // r 8 texels per pixel: level 3
  EXPECT_TRUE(near_rgba(pixel(3, 3), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(11, 1), {0, 0, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(23, 3), {0, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(3, 13), {255, 255, 255, 255}));
}

TEST_F(Texture3DTest, TrilinearBlendsTwoLevels) {
  load_coloured_chain();
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameterf(GL_TEXTURE_3D, GL_TEXTURE_MIN_LOD, 0.5f);  // lambda 0 clamped up to 0.5
  rect(0, 0, 8, 8, 0, 0, 1, 1, 0.5f, 0.5f);
  EXPECT_TRUE(near_rgba(pixel(4, 4), {128, 128, 0, 255}, 1));
}

TEST_F(Texture3DTest, IncompleteChainDisablesTheUnit) {
  load_coloured_chain();
  glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  const std::vector<uint8_t> t = solid_texels(4 * 4 * 2, {0, 0, 0, 255});
  glTexImage3D(GL_TEXTURE_3D, 1, GL_RGBA, 4, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());  // depth not halved
  glColor4ub(7, 8, 9, 255);
  rect(0, 0, 4, 4, 0, 0, 1, 1, 0, 0);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {7, 8, 9, 255}));
}

TEST_F(Texture3DTest, GenerateMipmapAveragesEightTexels) {
  glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
  std::vector<uint8_t> texels;
  for (int i = 0; i < 8; ++i)
    for (int c : Rgba{10 * i, 20 * i, 255, 8 * i}) texels.push_back(uint8_t(c));
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  GLint w = 0, h = 0, d = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 1, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 1, GL_TEXTURE_HEIGHT, &h);
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 1, GL_TEXTURE_DEPTH, &d);
  EXPECT_EQ(w, 1);
  EXPECT_EQ(h, 1);
  EXPECT_EQ(d, 1);
  uint8_t out[4] = {};
  glGetTexImage(GL_TEXTURE_3D, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  // (0 + 10 + ... + 70 + 4) / 8 = 35, (0 + ... + 140 + 4) / 8 = 70, (0 + ... + 56 + 4) / 8 = 28
  EXPECT_EQ(Rgba({out[0], out[1], out[2], out[3]}), Rgba({35, 70, 255, 28}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Texture3DTest, UnpackImageHeightAndSkipImages) {
  // Client images of 2x3 rows (IMAGE_HEIGHT 3, one padding row each), the first one skipped.
  std::vector<uint8_t> client;
  for (int image = 0; image < 3; ++image)
    for (int row = 0; row < 3; ++row)
      for (int x = 0; x < 2; ++x)
        for (int c : Rgba{image * 50, row * 50, x * 50, 255}) client.push_back(uint8_t(c));
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 3);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, client.data());
  glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
  glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
  std::vector<uint8_t> out(2 * 2 * 2 * 4);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 2; ++x) {
        const uint8_t* p = &out[((z * 2 + y) * 2 + x) * 4];
        EXPECT_EQ(Rgba({p[0], p[1], p[2], p[3]}), Rgba({(z + 1) * 50, y * 50, x * 50, 255})) << x << y << z;
      }
}

TEST_F(Texture3DTest, GetTexImagePacksWithImageHeightAndSkipImages) {
  load_cube(2);
  glPixelStorei(GL_PACK_IMAGE_HEIGHT, 3);
  glPixelStorei(GL_PACK_SKIP_IMAGES, 1);
  std::vector<uint8_t> out(4 * 3 * 2 * 4, 0xee);  // three images of 3 rows of 2 texels
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  for (int image = 0; image < 3; ++image)
    for (int row = 0; row < 3; ++row)
      for (int x = 0; x < 2; ++x) {
        const uint8_t* p = &out[((image * 3 + row) * 2 + x) * 4];
        const bool written = image >= 1 && row < 2;
        const Rgba expected = written ? cube_texel(x, row, image - 1) : Rgba{0xee, 0xee, 0xee, 0xee};
        EXPECT_EQ(Rgba({p[0], p[1], p[2], p[3]}), expected) << image << row << x;
      }
}

TEST_F(Texture3DTest, SubImageAndCopySubImageReplaceOneRegion) {
  load_cube(4);
  const std::vector<uint8_t> white = solid_texels(2 * 2, {255, 255, 255, 255});
  glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 2, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, white.data());
  glColor4ub(0, 200, 100, 255);
  glDisable(GL_TEXTURE_3D);
  glBegin(GL_QUADS);
  glVertex2f(0, 0);
  glVertex2f(2, 0);
  glVertex2f(2, 1);
  glVertex2f(0, 1);
  glEnd();
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 3, 3, 0, 0, 2, 1);  // to (0..1, 3) of slice 3
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  std::vector<uint8_t> out(4 * 4 * 4 * 4);
  glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  auto at = [&](int x, int y, int z) {
    const uint8_t* p = &out[((z * 4 + y) * 4 + x) * 4];
    return Rgba{p[0], p[1], p[2], p[3]};
  };
  EXPECT_EQ(at(1, 1, 2), Rgba({255, 255, 255, 255}));
  EXPECT_EQ(at(2, 2, 2), Rgba({255, 255, 255, 255}));
  EXPECT_EQ(at(0, 1, 2), cube_texel(0, 1, 2));
  EXPECT_EQ(at(1, 1, 1), cube_texel(1, 1, 1));
  EXPECT_EQ(at(0, 3, 3), Rgba({0, 200, 100, 255}));
  EXPECT_EQ(at(1, 3, 3), Rgba({0, 200, 100, 255}));
  EXPECT_EQ(at(2, 3, 3), cube_texel(2, 3, 3));
}

TEST_F(Texture3DTest, ErrorCodes) {
  const std::vector<uint8_t> texels = cube_texels(2);
  auto image = [&](GLenum target, GLint level, GLsizei w, GLsizei h, GLsizei d, GLint border) {
    glTexImage3D(target, level, GL_RGBA, w, h, d, border, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    return glGetError();
  };
  EXPECT_EQ(image(GL_TEXTURE_2D, 0, 2, 2, 2, 0), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(image(GL_TEXTURE_CUBE_MAP, 0, 2, 2, 2, 0), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(image(GL_TEXTURE_3D, -1, 2, 2, 2, 0), GLenum(GL_INVALID_VALUE));
  GLint max = 0;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max);
  ASSERT_GE(max, 16);
  int max_level = 0;
  while ((1 << (max_level + 1)) <= max) ++max_level;
  EXPECT_EQ(image(GL_TEXTURE_3D, max_level + 1, 1, 1, 1, 0), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(image(GL_TEXTURE_3D, 0, 2, 2, -1, 0), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(image(GL_TEXTURE_3D, 0, 2, 2, max + 1, 0), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(image(GL_TEXTURE_3D, 1, max, 1, 1, 0), GLenum(GL_INVALID_VALUE));  // level 1 is at most max / 2
  EXPECT_EQ(image(GL_TEXTURE_3D, 0, 2, 2, 2, 2), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(image(GL_TEXTURE_3D, 0, 1, 1, 1, 1), GLenum(GL_INVALID_VALUE));  // border 1 needs 2 + inner
  glTexImage3D(GL_TEXTURE_3D, 0, 0x1234, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE_3_3_2, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));

  // Sub-images: an undefined level, then out-of-range offsets and a proxy target.
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 1, 1, 1, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, -1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexSubImage3D(GL_PROXY_TEXTURE_3D, 0, 0, 0, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCopyTexSubImage3D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, 0, 1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 2, 0, 0, 1, 1);  // zoffset past the depth
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLint depth = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &depth);
  EXPECT_EQ(depth, 2);
  glGetTexLevelParameteriv(GL_TEXTURE_3D, max_level + 1, GL_TEXTURE_DEPTH, &depth);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(Texture3DTest, ProxyTakesTheSizeOnlyWhenItFits) {
  GLint max = 0, w = -1, d = -1;
  glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max);
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA8, 8, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &d);
  EXPECT_EQ(w, 8);
  EXPECT_EQ(d, 2);
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA8, 8, 4, max * 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &d);
  EXPECT_EQ(w, 0);
  EXPECT_EQ(d, 0);
}

TEST_F(Texture3DTest, DisplayListRecordsImagesButRunsProxiesAtOnce) {
  const std::vector<uint8_t> texels = cube_texels(2);
  glNewList(5, GL_COMPILE);
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 4, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glEndList();
  GLint w = 0;
  glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 4);  // the proxy ran while compiling
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 0);  // the image did not
  glCallList(5);
  glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &w);
  EXPECT_EQ(w, 2);
  rect(0, 0, 2, 2, 0, 0, 1, 1, 0.75f, 0.75f);
  EXPECT_TRUE(near_rgba(pixel(1, 0), cube_texel(1, 0, 1)));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Texture3DTest, ThreeDimensionsWinOverTwoAndOne) {
  load_cube(2);
  const std::vector<uint8_t> green = solid_texels(4, {0, 255, 0, 255});
  glBindTexture(GL_TEXTURE_2D, 2);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, green.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_1D);
  rect(0, 0, 2, 2, 0, 0, 1, 1, 0.25f, 0.25f);
  EXPECT_TRUE(near_rgba(pixel(0, 0), cube_texel(0, 0, 0)));
  glDisable(GL_TEXTURE_3D);
  rect(0, 0, 2, 2, 0, 0, 1, 1, 0.25f, 0.25f);
  EXPECT_TRUE(near_rgba(pixel(0, 0), {0, 255, 0, 255}));
}

}  // namespace
}  // namespace pineda::test
