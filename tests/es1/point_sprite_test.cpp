// OES_point_sprite in an OpenGL ES 1.1 context: the same machinery as desktop point sprites,
// reached through the GLfixed entry points; t runs from 0 at the top of the point.
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "tests/es1/egl_context.h"

namespace pineda::es1_test {
namespace {

constexpr int kSize = 32;
constexpr GLfixed X(double v) { return static_cast<GLfixed>(v * 65536.0); }

// Texel (i, j) of the 4x4 texture: a colour that names it.
std::vector<GLubyte> texel(int i, int j) { return {GLubyte(40 + 50 * i), GLubyte(40 + 50 * j), 7, 255}; }

class Es1PointSprite : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    glViewport(0, 0, kSize, kSize);
    glMatrixMode(GL_PROJECTION);
    glOrthox(0, X(kSize), 0, X(kSize), X(-1), X(1));
    glMatrixMode(GL_MODELVIEW);
    glClearColorx(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    std::vector<GLubyte> texels;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        for (GLubyte c : texel(i, j)) texels.push_back(c);
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
  }
  std::vector<GLubyte> pixel(int x, int y) {
    std::vector<GLubyte> p(4, 0);
    glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
    return p;
  }
  void point_at(GLfixed x, GLfixed y, GLfixed size) {
    const GLfixed position[] = {x, y};
    glPointSizex(size);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FIXED, 0, position);
    glDrawArrays(GL_POINTS, 0, 1);
    glDisableClientState(GL_VERTEX_ARRAY);
  }
  Es1Context ctx{kSize, kSize};
};

TEST_F(Es1PointSprite, Advertised) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_OES_point_sprite "), std::string::npos);
  EXPECT_EQ(glIsEnabled(GL_POINT_SPRITE_OES), GL_FALSE);
  GLfixed replace = -1;
  glGetTexEnvxv(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, &replace);
  EXPECT_EQ(replace, GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Es1PointSprite, ReplacedCoordinatesAcrossThePoint) {
  glEnable(GL_POINT_SPRITE_OES);
  glTexEnvx(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, GL_TRUE);
  GLfixed replace = -1;
  glGetTexEnvxv(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, &replace);
  EXPECT_EQ(replace, GL_TRUE);
  point_at(X(10), X(10), X(4));  // pixels 8..11
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) EXPECT_EQ(pixel(8 + i, 11 - j), texel(i, j)) << i << "," << j;
  EXPECT_EQ(pixel(12, 12), (std::vector<GLubyte>{0, 0, 0, 0}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Es1PointSprite, NoCoordinateOriginInEs) {
  glPointParameterx(0x8CA0 /* GL_POINT_SPRITE_COORD_ORIGIN */, 0x8CA1 /* GL_LOWER_LEFT */);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexEnvx(GL_POINT_SPRITE_OES, GL_COORD_REPLACE_OES, 2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

}  // namespace
}  // namespace pineda::es1_test
