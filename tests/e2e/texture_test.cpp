// Texture sampling: NEAREST texels exactly, LINEAR at texel centres, REPEAT and CLAMP,
// 1D textures, TexSubImage, and the texture environment modes.
#include <algorithm>
#include <cmath>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/texel_images.h"
#include "tests/e2e/support/window_quad.h"

namespace pineda::test {
namespace {

class TextureTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glBindTexture(GL_TEXTURE_2D, 1);
    const std::vector<uint8_t> texels = grid_texels();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  }
  void textured_rect(float x0, float y0, float x1, float y1, float s0, float t0, float s1, float t1) {
    draw_textured_rect(x0, y0, x1, y1, s0, t0, s1, t1);
  }
};

TEST_F(TextureTest, NearestMagnificationGivesExactTexels) {
  textured_rect(0, 0, 8, 8, 0, 0, 1, 1);  // each texel covers 2x2 pixels
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_TRUE(near_rgba(pixel(x, y), grid_texel(x / 2, y / 2))) << x << "," << y;
  EXPECT_TRUE(near_rgba(pixel(8, 8), {0, 0, 0, 0}));
  expect_osmesa_buffer_matches_readback();
}

TEST_F(TextureTest, LinearAtTexelCentresGivesTheTexels) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  textured_rect(0, 0, 4, 4, 0, 0, 1, 1);  // pixel centres land on texel centres
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_TRUE(near_rgba(pixel(x, y), grid_texel(x, y), 1)) << x << "," << y;
}

TEST_F(TextureTest, LinearBetweenTexelCentresAverages) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  // 8 pixels across 4 texels: pixel centre x + .5 maps to u = (x + .5) / 2, so pixels 1..6
  // sit a quarter texel from the nearest centre.
  textured_rect(0, 0, 8, 8, 0, 0, 1, 1);
  for (int x = 1; x < 7; ++x) {
    const double u = (x + 0.5) / 2 - 0.5;
    const int i0 = int(std::floor(u));
    const double a = u - i0;
    const double red = (1 - a) * (40 * i0 + 10) + a * (40 * (i0 + 1) + 10);
    EXPECT_NEAR(pixel(x, 3)[0], red, 1.0) << x;
  }
}

TEST_F(TextureTest, RepeatWraps) {
  textured_rect(0, 0, 16, 16, 0, 0, 2, 2);  // two periods, 2x2 pixels per texel
  for (int y = 0; y < 16; y += 3)
    for (int x = 0; x < 16; ++x)
      EXPECT_TRUE(near_rgba(pixel(x, y), grid_texel((x / 2) % 4, (y / 2) % 4))) << x << "," << y;
}

TEST_F(TextureTest, NegativeCoordinatesRepeat) {
  textured_rect(0, 0, 8, 8, -1, -1, 0, 0);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_TRUE(near_rgba(pixel(x, y), grid_texel(x / 2, y / 2))) << x << "," << y;
}

TEST_F(TextureTest, ClampHoldsTheEdgeTexelsWithNearest) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
  // s from -1 to 2 over 12 pixels: s = (x + .5) / 4 - 1.
  textured_rect(0, 0, 12, 12, -1, -1, 2, 2);
  for (int y = 0; y < 12; y += 2)
    for (int x = 0; x < 12; ++x) {
      auto texel_of = [](int p) {
        const double s = (p + 0.5) / 4 - 1;
        return std::clamp(int(std::floor(std::clamp(s, 0.0, 1.0) * 4)), 0, 3);
      };
      EXPECT_TRUE(near_rgba(pixel(x, y), grid_texel(texel_of(x), texel_of(y)))) << x << "," << y;
    }
}

TEST_F(TextureTest, ClampToEdgeWithLinearNeverReadsTheBorder) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  const GLfloat border[4] = {1, 0, 1, 1};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  textured_rect(0, 0, 8, 8, -1, -1, 0, 0);  // entirely left of and below the texture
  EXPECT_TRUE(near_rgba(pixel(4, 4), grid_texel(0, 0), 1));
  clear_to(0, 0, 0, 0);
  textured_rect(0, 0, 8, 8, 1, 1, 2, 2);
  EXPECT_TRUE(near_rgba(pixel(4, 4), grid_texel(3, 3), 1));
}

TEST_F(TextureTest, SubImageReplacesTexels) {
  const uint8_t white[2 * 4] = {255, 255, 255, 255, 255, 255, 255, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  textured_rect(0, 0, 4, 4, 0, 0, 1, 1);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const bool replaced = y == 2 && (x == 1 || x == 2);
      EXPECT_TRUE(near_rgba(pixel(x, y), replaced ? Rgba{255, 255, 255, 255} : grid_texel(x, y))) << x << "," << y;
    }
}

TEST_F(TextureTest, ChangingATextureAfterADrawDoesNotChangeThatDraw) {
  textured_rect(0, 0, 4, 4, 0, 0, 1, 1);
  const uint8_t black[4] = {0, 0, 0, 255};
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, black);
  textured_rect(8, 0, 12, 4, 0, 0, 1, 1);
  EXPECT_TRUE(near_rgba(pixel(0, 0), grid_texel(0, 0)));
  EXPECT_TRUE(near_rgba(pixel(8, 0), {0, 0, 0, 255}));
}

TEST_F(TextureTest, IncompleteMipmappedTextureDisablesTexturing) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);  // no levels 1, 2
  glColor3f(0, 1, 0);
  textured_rect(0, 0, 4, 4, 0, 0, 1, 1);
  EXPECT_TRUE(near_rgba(pixel(1, 1), {0, 255, 0, 255}));
}

TEST_F(TextureTest, MipmapLevelSelectedOnMinification) {
  const uint8_t level1[2 * 2 * 4] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
  const uint8_t level2[4] = {0, 0, 255, 255};
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, level1);
  glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, level2);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  textured_rect(0, 0, 2, 2, 0, 0, 1, 1);  // 4 texels per 2 pixels: lambda = 1
  EXPECT_TRUE(near_rgba(pixel(0, 0), {255, 0, 0, 255}));
  textured_rect(4, 4, 5, 5, 0, 0, 1, 1);  // lambda = 2
  EXPECT_TRUE(near_rgba(pixel(4, 4), {0, 0, 255, 255}));
}

TEST_F(TextureTest, OneDimensionalTexture) {
  glDisable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_1D, 2);
  const uint8_t texels[4 * 3] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_1D);
  textured_rect(0, 0, 8, 2, 0, 0, 1, 0);
  const Rgba expected[4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
  for (int x = 0; x < 8; ++x) EXPECT_TRUE(near_rgba(pixel(x, 1), expected[x / 2])) << x;
}

TEST_F(TextureTest, UnpackRowLengthAndSkips) {
  // A 6x3 client image of which the 2x2 block at (3, 1) is loaded.
  std::vector<uint8_t> image(6 * 3 * 4, 0);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 6; ++x) {
      uint8_t* p = &image[(y * 6 + x) * 4];
      p[0] = uint8_t(x * 40);
      p[1] = uint8_t(y * 80);
      p[2] = 7;
      p[3] = 255;
    }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 6);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  textured_rect(0, 0, 2, 2, 0, 0, 1, 1);
  EXPECT_TRUE(near_rgba(pixel(0, 0), {120, 80, 7, 255}));
  EXPECT_TRUE(near_rgba(pixel(1, 0), {160, 80, 7, 255}));
  EXPECT_TRUE(near_rgba(pixel(0, 1), {120, 160, 7, 255}));
  EXPECT_TRUE(near_rgba(pixel(1, 1), {160, 160, 7, 255}));
}

TEST_F(TextureTest, TextureMatrixTransformsCoordinates) {
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.5f, 0, 0);  // shift by two texels
  glMatrixMode(GL_MODELVIEW);
  textured_rect(0, 0, 4, 4, 0, 0, 1, 1);
  for (int x = 0; x < 4; ++x) EXPECT_TRUE(near_rgba(pixel(x, 0), grid_texel((x + 2) % 4, 0))) << x;
}

// ---- Texture environment: one texel T against the fragment colour C. ----

struct EnvCase {
  GLenum mode;
  GLenum internal_format;
};

class TexEnvModeTest : public GlTest, public ::testing::WithParamInterface<EnvCase> {};

TEST_P(TexEnvModeTest, MatchesTheSpecTable) {
  const EnvCase e = GetParam();
  pixel_projection();
  clear_to(0, 0, 0, 0);
  const uint8_t texel[4] = {128, 64, 255, 102};
  glBindTexture(GL_TEXTURE_2D, 3);
  glTexImage2D(GL_TEXTURE_2D, 0, e.internal_format, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, e.mode);
  const GLfloat env[4] = {0.2f, 0.6f, 1.0f, 0.4f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
  const double c[4] = {0.5, 1.0, 0.25, 0.8};
  glColor4d(c[0], c[1], c[2], c[3]);
  glRecti(0, 0, 4, 4);

  // The texture's components by base format (GL 1.1 spec Table 3.15).
  const double tr = 128 / 255.0, tg = 64 / 255.0, tb = 1.0, ta = 102 / 255.0;
  double t[4];
  bool has_rgb = true, has_alpha = true;
  switch (e.internal_format) {
    case GL_RGB: t[0] = tr; t[1] = tg; t[2] = tb; t[3] = 1; has_alpha = false; break;
    case GL_LUMINANCE: t[0] = t[1] = t[2] = tr; t[3] = 1; has_alpha = false; break;
    case GL_ALPHA: t[0] = t[1] = t[2] = 0; t[3] = ta; has_rgb = false; break;
    case GL_INTENSITY: t[0] = t[1] = t[2] = t[3] = tr; break;
    default: t[0] = tr; t[1] = tg; t[2] = tb; t[3] = ta;
  }
  double out[4];
  for (int i = 0; i < 3; ++i) {
    switch (e.mode) {
      case GL_MODULATE: out[i] = has_rgb ? c[i] * t[i] : c[i]; break;
      case GL_REPLACE: out[i] = has_rgb ? t[i] : c[i]; break;
      case GL_DECAL: out[i] = has_alpha ? c[i] * (1 - t[3]) + t[i] * t[3] : t[i]; break;
      case GL_BLEND: out[i] = has_rgb ? c[i] * (1 - t[i]) + env[i] * t[i] : c[i]; break;
      case GL_ADD: out[i] = has_rgb ? std::min(c[i] + t[i], 1.0) : c[i]; break;
    }
  }
  const bool intensity = e.internal_format == GL_INTENSITY;
  switch (e.mode) {
    case GL_MODULATE: case GL_ADD: out[3] = has_alpha ? c[3] * t[3] : c[3]; break;
    case GL_REPLACE: out[3] = has_alpha ? t[3] : c[3]; break;
    case GL_DECAL: out[3] = c[3]; break;
    case GL_BLEND: out[3] = intensity ? c[3] * (1 - t[3]) + env[3] * t[3] : has_alpha ? c[3] * t[3] : c[3]; break;
  }
  if (e.mode == GL_ADD && intensity) out[3] = std::min(c[3] + t[3], 1.0);
  EXPECT_TRUE(near_rgba(pixel(2, 2), {to_byte(out[0]), to_byte(out[1]), to_byte(out[2]), to_byte(out[3])}, 2))
      << "mode " << std::hex << e.mode << " format " << e.internal_format;
}

INSTANTIATE_TEST_SUITE_P(
    Modes, TexEnvModeTest,
    ::testing::Values(EnvCase{GL_MODULATE, GL_RGBA}, EnvCase{GL_MODULATE, GL_RGB}, EnvCase{GL_MODULATE, GL_LUMINANCE},
                      EnvCase{GL_MODULATE, GL_ALPHA}, EnvCase{GL_MODULATE, GL_INTENSITY},
                      EnvCase{GL_REPLACE, GL_RGBA}, EnvCase{GL_REPLACE, GL_RGB}, EnvCase{GL_REPLACE, GL_ALPHA},
                      EnvCase{GL_DECAL, GL_RGBA}, EnvCase{GL_DECAL, GL_RGB}, EnvCase{GL_BLEND, GL_RGBA},
                      EnvCase{GL_BLEND, GL_LUMINANCE}, EnvCase{GL_BLEND, GL_INTENSITY}, EnvCase{GL_ADD, GL_RGBA},
                      EnvCase{GL_ADD, GL_RGB}));

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// A 1D texture with a border: the client image is width + 2 texels in one row.
TEST_F(TextureTest, OneDimensionalTextureWithBorderSkipsTheBorderTexels) {
  glDisable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_1D, 4);
  const uint8_t texels[6 * 3] = {9, 9, 9, 255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255, 9, 9, 9};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 6, 1, GL_RGB, GL_UNSIGNED_BYTE, texels);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_1D);
  textured_rect(0, 0, 8, 2, 0, 0, 1, 0);
  const Rgba expected[4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
  for (int x = 0; x < 8; ++x) EXPECT_TRUE(near_rgba(pixel(x, 1), expected[x / 2])) << x;
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(TextureTest, DeletingATextureAfterADrawKeepsThatDrawsTexels) {
  textured_rect(0, 0, 8, 8, 0, 0, 1, 1);
  GLuint name = 1;
  glDeleteTextures(1, &name);  // before the queued draw is rasterized
  const std::vector<uint8_t> junk(64 * 64 * 4, 0x55);
  glBindTexture(GL_TEXTURE_2D, 1);  // a new texture under the same name
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, junk.data());
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) EXPECT_TRUE(near_rgba(pixel(x, y), grid_texel(x / 2, y / 2))) << x << "," << y;
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(TextureTest, MirroredRepeatReflectsEveryOtherPeriod) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  textured_rect(0, 0, 16, 2, 0, 0.1f, 2, 0.1f);  // s from 0 to 2: texels 0 1 2 3 3 2 1 0; t in row 0
  const int expected[8] = {0, 1, 2, 3, 3, 2, 1, 0};
  for (int x = 0; x < 16; ++x) EXPECT_TRUE(near_rgba(pixel(x, 0), grid_texel(expected[x / 2], 0))) << x;
}

TEST_F(TextureTest, ClampToBorderGivesTheBorderColourOutside) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  const GLfloat border[4] = {1, 0, 1, 1};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
  textured_rect(0, 0, 16, 2, -1, 0.1f, 1, 0.1f);  // left half outside the texture; t in row 0
  EXPECT_TRUE(near_rgba(pixel(3, 0), {255, 0, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(9, 0), grid_texel(0, 0)));
  EXPECT_TRUE(near_rgba(pixel(15, 0), grid_texel(3, 0)));
}

}  // namespace
}  // namespace pineda::test
