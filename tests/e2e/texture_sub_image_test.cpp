// glTexSubImage and glCopyTexSubImage while draws use the texture: a queued draw samples the
// texels it was recorded with, every later draw the replaced ones, whichever level, cube face
// or 3D slice was replaced (the sampled image reads the texture's texels where they are; they
// are copied apart from it first when a queued draw holds it).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/texel_images.h"
#include "tests/e2e/support/window_quad.h"

// Its own namespace: a unity batch holds other files' colour names.
namespace pineda::test::sub_image {
namespace {

constexpr Rgba kRed{255, 0, 0, 255}, kBlue{0, 0, 255, 255}, kGreen{0, 255, 0, 255};

void set_texel(GLenum target, GLint level, int s, int t, const Rgba& c) {
  const uint8_t texel[4] = {uint8_t(c[0]), uint8_t(c[1]), uint8_t(c[2]), uint8_t(c[3])};
  glTexSubImage2D(target, level, s, t, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, texel);
}

void nearest(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

class TextureSubImageTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  }
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
  // The 4x4 grid texture drawn over [x, x + 8) x [0, 8): texel (s, t) covers 2x2 pixels.
  void draw_grid_at(float x) { draw_textured_rect(x, 0, x + 8, 8, 0, 0, 1, 1); }
  // The texels a draw_grid_at(x) shows, against `expected(s, t)`.
  template <typename Expected>
  void expect_grid_at(int x, Expected expected) {
    for (int t = 0; t < 4; ++t)
      for (int s = 0; s < 4; ++s) EXPECT_TRUE(near_rgba(pixel(x + 2 * s, 2 * t), expected(s, t))) << s << "," << t;
  }
};

TEST_F(TextureSubImageTest, EachDrawSamplesTheTexelsOfItsTime) {
  glBindTexture(GL_TEXTURE_2D, 1);
  const std::vector<uint8_t> grid = grid_texels();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, grid.data());
  nearest(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_2D);
  draw_grid_at(0);
  set_texel(GL_TEXTURE_2D, 0, 1, 1, kRed);  // while the first draw is queued
  draw_grid_at(8);
  expect_grid_at(0, grid_texel);
  set_texel(GL_TEXTURE_2D, 0, 2, 3, kBlue);  // no draw queued now
  draw_grid_at(16);
  expect_grid_at(8, [](int s, int t) { return s == 1 && t == 1 ? kRed : grid_texel(s, t); });
  expect_grid_at(16, [](int s, int t) {
    return s == 1 && t == 1 ? kRed : s == 2 && t == 3 ? kBlue : grid_texel(s, t);
  });
}

// The second level replaced, with the base level at 1: the sampled image's first level is the
// texture's level 1, and level 0's texels are not sampled at all.
TEST_F(TextureSubImageTest, ALevelAboveTheBaseLevel) {
  glBindTexture(GL_TEXTURE_2D, 1);
  const std::vector<uint8_t> grid = grid_texels();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, grid.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 1);
  nearest(GL_TEXTURE_2D);
  glEnable(GL_TEXTURE_2D);
  draw_grid_at(0);
  expect_grid_at(0, grid_texel);
  set_texel(GL_TEXTURE_2D, 1, 3, 0, kGreen);
  set_texel(GL_TEXTURE_2D, 0, 0, 0, kRed);
  draw_grid_at(8);
  expect_grid_at(8, [](int s, int t) { return s == 3 && t == 0 ? kGreen : grid_texel(s, t); });
}

// A cube map of 1x1 faces, face i the colour (30 i, 0, 0): replacing -Y changes only what
// the -Y direction samples.
TEST_F(TextureSubImageTest, OneFaceOfACubeMap) {
  glBindTexture(GL_TEXTURE_CUBE_MAP, 1);
  for (int f = 0; f < 6; ++f) {
    const uint8_t texel[4] = {uint8_t(30 * f), 0, 0, 255};
    glTexImage2D(GLenum(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  }
  nearest(GL_TEXTURE_CUBE_MAP);
  glEnable(GL_TEXTURE_CUBE_MAP);
  const float directions[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  auto draw_faces = [&] {
    for (int f = 0; f < 6; ++f) {
      glTexCoord3fv(directions[f]);
      glRectf(float(2 * f), 0, float(2 * f + 2), 2);
    }
  };
  draw_faces();
  for (int f = 0; f < 6; ++f) EXPECT_TRUE(near_rgba(pixel(2 * f, 0), {30 * f, 0, 0, 255})) << f;
  set_texel(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, 0, 0, kBlue);
  draw_faces();
  for (int f = 0; f < 6; ++f) EXPECT_TRUE(near_rgba(pixel(2 * f, 0), f == 3 ? kBlue : Rgba{30 * f, 0, 0, 255})) << f;
}

// A 1x1x4 3D texture, slice r the colour (0, 50 r, 0): replacing slice 2 changes only it.
TEST_F(TextureSubImageTest, OneSliceOfA3DTexture) {
  glBindTexture(GL_TEXTURE_3D, 1);
  const uint8_t slices[16] = {0, 0, 0, 255, 0, 50, 0, 255, 0, 100, 0, 255, 0, 150, 0, 255};
  glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, slices);
  nearest(GL_TEXTURE_3D);
  glEnable(GL_TEXTURE_3D);
  auto draw_slices = [] {
    for (int r = 0; r < 4; ++r) {
      glTexCoord3f(0.5f, 0.5f, (float(r) + 0.5f) / 4.f);
      glRectf(float(2 * r), 0, float(2 * r + 2), 2);
    }
  };
  draw_slices();
  for (int r = 0; r < 4; ++r) EXPECT_TRUE(near_rgba(pixel(2 * r, 0), {0, 50 * r, 0, 255})) << r;
  const uint8_t red[4] = {255, 0, 0, 255};
  glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  draw_slices();
  for (int r = 0; r < 4; ++r) EXPECT_TRUE(near_rgba(pixel(2 * r, 0), r == 2 ? kRed : Rgba{0, 50 * r, 0, 255})) << r;
}

// glCopyTexSubImage2D from the window into a texture drawn each time: every draw shows the
// frame as it was when copied.
TEST_F(TextureSubImageTest, CopiesOfTheFrameBetweenDraws) {
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  nearest(GL_TEXTURE_2D);
  for (int i = 0; i < 3; ++i) {
    glDisable(GL_TEXTURE_2D);
    glColor4ub(GLubyte(60 * i + 20), GLubyte(200 - 60 * i), 7, 255);
    glRecti(20, 20, 24, 24);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 20, 20, 4, 4);
    glEnable(GL_TEXTURE_2D);
    draw_textured_rect(float(8 * i), 0, float(8 * i + 4), 4, 0, 0, 1, 1);
  }
  for (int i = 0; i < 3; ++i)
    EXPECT_TRUE(near_rgba(pixel(8 * i + 1, 1), {60 * i + 20, 200 - 60 * i, 7, 255})) << i;
}

// One texture sampled through two images at once (its own filter, and a sampler object's
// mipmapped one): both queued draws keep the texels of their time.
TEST_F(TextureSubImageTest, QueuedDrawsThroughASamplerObjectAndWithout) {
  glBindTexture(GL_TEXTURE_2D, 1);
  const std::vector<uint8_t> grid = grid_texels();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, grid.data());
  const uint8_t grey[4 * 4] = {90, 90, 90, 255, 90, 90, 90, 255, 90, 90, 90, 255, 90, 90, 90, 255};
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, grey);
  glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, grey);
  nearest(GL_TEXTURE_2D);
  GLuint sampler = 0;
  glGenSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glEnable(GL_TEXTURE_2D);
  draw_grid_at(0);  // magnified: level 0 either way
  glBindSampler(0, sampler);
  draw_grid_at(8);
  set_texel(GL_TEXTURE_2D, 0, 1, 1, kRed);  // both draws queued
  draw_grid_at(16);
  glBindSampler(0, 0);
  draw_grid_at(24);
  expect_grid_at(0, grid_texel);
  expect_grid_at(8, grid_texel);
  const auto replaced = [](int s, int t) { return s == 1 && t == 1 ? kRed : grid_texel(s, t); };
  expect_grid_at(16, replaced);
  expect_grid_at(24, replaced);
  glDeleteSamplers(1, &sampler);
}

// A texture rendered into through a framebuffer object, drawn into the window, then changed by
// glTexSubImage while that draw is queued: the framebuffer renders into the texels the texture
// has after the change, and the queued draw shows the ones of its time.
TEST_F(TextureSubImageTest, RenderedIntoAroundAChangeWhileADrawIsQueued) {
  glBindTexture(GL_TEXTURE_2D, 1);
  const std::vector<uint8_t> grid = grid_texels();
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, grid.data());
  nearest(GL_TEXTURE_2D);
  GLuint fb = 0;
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 1, 0);
  ASSERT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  auto render_texel = [&](int s, int t, const Rgba& c) {  // texel (s, t) by drawing into it
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glViewport(0, 0, 4, 4);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(0, 4, 0, 4, -1, 1);
    glDisable(GL_TEXTURE_2D);
    glColor4ub(GLubyte(c[0]), GLubyte(c[1]), GLubyte(c[2]), GLubyte(c[3]));
    glRecti(s, t, s + 1, t + 1);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width(), height());
    glEnable(GL_TEXTURE_2D);
  };
  render_texel(0, 0, kGreen);
  draw_grid_at(0);
  set_texel(GL_TEXTURE_2D, 0, 1, 1, kRed);  // while the draw at 0 is queued
  render_texel(3, 3, kBlue);
  draw_grid_at(8);
  expect_grid_at(0, [](int s, int t) { return s == 0 && t == 0 ? kGreen : grid_texel(s, t); });
  expect_grid_at(8, [](int s, int t) {
    return s == 0 && t == 0 ? kGreen : s == 1 && t == 1 ? kRed : s == 3 && t == 3 ? kBlue : grid_texel(s, t);
  });
  glDeleteFramebuffers(1, &fb);
}

}  // namespace
}  // namespace pineda::test::sub_image
