// OES_draw_texture: glDrawTex*OES draws a window-aligned rectangle textured through the crop
// rectangle of each enabled unit's texture, ignoring transforms; the fragment pipeline applies.
#define GL_GLEXT_PROTOTYPES
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <gtest/gtest.h>

#include <vector>

#include "tests/es1/egl_context.h"

namespace pineda::es1_test {
namespace {

constexpr int kSize = 32;
constexpr GLfixed X(double v) { return static_cast<GLfixed>(v * 65536.0); }
using Pixel = std::vector<GLubyte>;

// Texel (i, j) of the 4x4 texture: a colour that names it (row j = 0 at the bottom).
Pixel texel(int i, int j) { return {GLubyte(40 + 50 * i), GLubyte(40 + 50 * j), 7, 255}; }

class DrawTexture : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    glViewport(0, 0, kSize, kSize);
    glClearColorx(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    std::vector<GLubyte> texels;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        for (GLubyte c : texel(i, j)) texels.push_back(c);
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
  }
  void crop(GLint u, GLint v, GLint w, GLint h) {
    const GLint rect[] = {u, v, w, h};
    glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, rect);
  }
  Pixel pixel(int x, int y) {
    Pixel p(4, 0);
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
    return p;
  }
  int drawn_pixels() {
    std::vector<GLubyte> all(kSize * kSize * 4);
    glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, all.data());
    int n = 0;
    for (int i = 0; i < kSize * kSize; ++i) n += all[4 * i] || all[4 * i + 1] || all[4 * i + 2] || all[4 * i + 3];
    return n;
  }
  Es1Context ctx{kSize, kSize};
  GLuint texture = 0;
};

TEST_F(DrawTexture, CropRectState) {
  GLint rect[4] = {-1, -1, -1, -1};
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, rect);
  EXPECT_EQ(std::vector<GLint>(rect, rect + 4), (std::vector<GLint>{0, 0, 0, 0}));
  crop(1, 2, -3, 40);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, rect);
  EXPECT_EQ(std::vector<GLint>(rect, rect + 4), (std::vector<GLint>{1, 2, -3, 40}));
  const GLfixed fixed[] = {5, 6, 7, 8};  // integers, not 16.16
  glTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, fixed);
  GLfloat f[4] = {};
  glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, f);
  EXPECT_EQ(std::vector<GLfloat>(f, f + 4), (std::vector<GLfloat>{5, 6, 7, 8}));
  const GLfloat floats[] = {1.f, 2.f, 3.f, 4.f};
  glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, floats);
  GLfixed x[4] = {};
  glGetTexParameterxv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, x);
  EXPECT_EQ(std::vector<GLfixed>(x, x + 4), (std::vector<GLfixed>{1, 2, 3, 4}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, 1);  // a vector parameter
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  // Each texture has its own.
  GLuint other = 0;
  glGenTextures(1, &other);
  glBindTexture(GL_TEXTURE_2D, other);
  glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_CROP_RECT_OES, rect);
  EXPECT_EQ(std::vector<GLint>(rect, rect + 4), (std::vector<GLint>{0, 0, 0, 0}));
}

TEST_F(DrawTexture, OneTexelPerPixel) {
  crop(0, 0, 4, 4);
  glDrawTexiOES(8, 8, 0, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(drawn_pixels(), 16);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) EXPECT_EQ(pixel(8 + i, 8 + j), texel(i, j)) << i << "," << j;
}

TEST_F(DrawTexture, CropAndStretch) {
  crop(1, 1, 2, 2);  // texels 1..2 in each direction, two pixels each
  glDrawTexfOES(0.f, 0.f, 0.f, 4.f, 4.f);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_EQ(pixel(x, y), texel(1 + x / 2, 1 + y / 2)) << x << "," << y;
  EXPECT_EQ(drawn_pixels(), 16);
}

TEST_F(DrawTexture, NegativeCropWidthMirrors) {
  crop(4, 0, -4, 4);
  const GLshort coords[] = {2, 2, 0, 4, 4};
  glDrawTexsvOES(coords);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(pixel(2 + i, 2), texel(3 - i, 0)) << i;
}

TEST_F(DrawTexture, TransformsAndViewportAreIgnored) {
  crop(0, 0, 4, 4);
  glViewport(20, 20, 4, 4);
  glMatrixMode(GL_MODELVIEW);
  glTranslatex(X(5), X(5), 0);
  glMatrixMode(GL_TEXTURE);
  glScalex(X(2), X(2), X(1));
  glEnable(GL_LIGHTING);
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT_AND_BACK);
  const GLfixed coords[] = {X(8), X(8), 0, X(4), X(4)};
  glDrawTexxvOES(coords);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) EXPECT_EQ(pixel(8 + i, 8 + j), texel(i, j)) << i << "," << j;
  EXPECT_EQ(drawn_pixels(), 16);
}

TEST_F(DrawTexture, ScissorAndCurrentColourApply) {
  crop(0, 0, 4, 4);
  glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glColor4x(X(1), 0, X(1), X(1));  // green is removed
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 10, 32);
  glDrawTexiOES(8, 8, 0, 4, 4);
  EXPECT_EQ(drawn_pixels(), 8);
  EXPECT_EQ(pixel(9, 10), (Pixel{90, 0, 7, 255}));
}

TEST_F(DrawTexture, DepthIsZMappedThroughTheDepthRange) {
  crop(0, 0, 4, 4);
  glClearDepthx(X(1));
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthRangex(0, X(0.5));  // z = 0.5 is window depth 0.25
  glDrawTexfOES(0.f, 0.f, 0.5f, 4.f, 4.f);
  EXPECT_EQ(drawn_pixels(), 16);
  glDisable(GL_TEXTURE_2D);
  glColor4x(X(1), X(1), X(1), X(1));
  glDepthRangex(0, X(1));
  glDrawTexfOES(0.f, 0.f, 0.3f, 4.f, 4.f);  // depth 0.3: behind
  EXPECT_EQ(pixel(1, 1), texel(1, 1));
  glDrawTexfOES(0.f, 0.f, 0.2f, 4.f, 4.f);  // depth 0.2: in front
  EXPECT_EQ(pixel(1, 1), (Pixel{255, 255, 255, 255}));
  glColor4x(X(1), 0, 0, X(1));
  glDrawTexfOES(0.f, 0.f, -3.f, 2.f, 2.f);  // clamped to 0: in front
  glDrawTexfOES(2.f, 0.f, 7.f, 2.f, 2.f);   // clamped to 1: behind
  EXPECT_EQ(pixel(1, 1), (Pixel{255, 0, 0, 255}));
  EXPECT_EQ(pixel(3, 1), (Pixel{255, 255, 255, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(DrawTexture, BadSizes) {
  crop(0, 0, 4, 4);
  glDrawTexiOES(0, 0, 0, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDrawTexfOES(0.f, 0.f, 0.f, 4.f, -1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(drawn_pixels(), 0);
  // Non-finite positions draw nothing and crash nothing.
  glDrawTexfOES(1e30f, 0.f, 0.f, 4.f, 4.f);
  glDrawTexfOES(0.f, 0.f, 0.f, 1e30f, 1e30f);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::es1_test
