// GL 2.0 point sprites (ARB_point_sprite): a point drawn as a square of its exact size whose
// replaced texture coordinates run from s = 0 at the left to 1 at the right, and t from 0 at
// the top (UPPER_LEFT, the default) or the bottom (LOWER_LEFT). Exact texels of a 4x4 texture.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/texel_images.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

// Texel (i, j) of the 4x4 texture: a colour that names it.
Rgba texel(int i, int j) { return {40 + 50 * i, 40 + 50 * j, 7, 255}; }

class PointSpriteTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    std::vector<uint8_t> texels;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        for (int c : texel(i, j)) texels.push_back(uint8_t(c));
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
  }
  void TearDown() override {
    glDeleteTextures(1, &texture_);
    GlTest::TearDown();
  }
  void sprites_on() {
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  }
  void point(float x, float y, float size) {
    glPointSize(size);
    glBegin(GL_POINTS);
    glTexCoord2f(0.9f, 0.1f);  // texel (3, 0) where the coordinates are not replaced
    glVertex2f(x, y);
    glEnd();
  }
  // Pixels with any colour.
  int drawn_pixels() { return width() * height() - count_pixels({0, 0, 0, 0}); }
  GLuint texture_ = 0;
};

TEST_F(PointSpriteTest, Defaults) {
  EXPECT_EQ(glIsEnabled(GL_POINT_SPRITE), GL_FALSE);
  EXPECT_EQ(get_bool(GL_POINT_SPRITE), GL_FALSE);
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_UPPER_LEFT);
  for (int unit = 0; unit < 4; ++unit) {
    glActiveTexture(GL_TEXTURE0 + unit);
    GLint replace = -1;
    glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &replace);
    EXPECT_EQ(replace, GL_FALSE);
  }
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_ARB_point_sprite "), std::string::npos);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(PointSpriteTest, UpperLeftOriginTexels) {
  sprites_on();
  point(10.f, 10.f, 4.f);  // pixels 8..11 in x and y
  EXPECT_EQ(drawn_pixels(), 16);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)  // s grows to the right; t grows downwards: row 0 at the top
      EXPECT_TRUE(near_rgba(pixel(8 + i, 11 - j), texel(i, j))) << i << "," << j;
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(PointSpriteTest, LowerLeftOriginTexels) {
  sprites_on();
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_LOWER_LEFT);
  point(10.f, 10.f, 4.f);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(near_rgba(pixel(8 + i, 8 + j), texel(i, j))) << i << "," << j;
}

TEST_F(PointSpriteTest, OddSizeOnAPixelCentre) {
  sprites_on();
  glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, GLfloat(GL_LOWER_LEFT));
  point(10.5f, 10.5f, 3.f);  // pixels 9..11; s at their centres 1/6, 1/2, 5/6
  EXPECT_EQ(drawn_pixels(), 9);
  const int texel_of[3] = {0, 2, 3};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      EXPECT_TRUE(near_rgba(pixel(9 + i, 9 + j), texel(texel_of[i], texel_of[j]))) << i << "," << j;
}

TEST_F(PointSpriteTest, FractionalSizeCoversTheCentresInsideItsSquare) {
  sprites_on();
  point(10.f, 10.f, 2.5f);  // the square [8.75, 11.25]: centres 9.5 and 10.5
  EXPECT_EQ(drawn_pixels(), 4);
  // s = 1/2 + (9.5 - 10) / 2.5 = 0.3 and 0.7: texels 1 and 2.
  EXPECT_TRUE(near_rgba(pixel(9, 10), texel(1, 1)));
  EXPECT_TRUE(near_rgba(pixel(10, 9), texel(2, 2)));
  // Without sprites, an aliased point of 2.5 is rounded to 3 pixels a side.
  glDisable(GL_POINT_SPRITE);
  clear_to(0, 0, 0, 0);
  point(10.f, 10.f, 2.5f);
  EXPECT_EQ(drawn_pixels(), 9);
}

TEST_F(PointSpriteTest, CentresOnTheSquaresEdgesGoToTheLeftAndBottomOnes) {
  sprites_on();
  point(10.f, 10.f, 1.f);  // the square [9.5, 10.5]: the centres of pixels 9 and 10 on its edges
  EXPECT_EQ(drawn_pixels(), 1);
  EXPECT_TRUE(near_rgba(pixel(9, 9), texel(0, 0)));  // s = 0, t = 1 (REPEAT: row 0)
}

TEST_F(PointSpriteTest, UnreplacedUnitsKeepTheVertexCoordinates) {
  glEnable(GL_POINT_SPRITE);  // COORD_REPLACE stays FALSE
  point(10.f, 10.f, 4.f);
  EXPECT_EQ(count_pixels(texel(3, 0)), 16);
  // And with sprites off, the same.
  glDisable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  clear_to(0, 0, 0, 0);
  point(10.f, 10.f, 4.f);
  EXPECT_EQ(count_pixels(texel(3, 0)), 16);
}

TEST_F(PointSpriteTest, CoordReplaceIsPerUnit) {
  glEnable(GL_POINT_SPRITE);
  glActiveTexture(GL_TEXTURE1);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  GLint replace = -1;
  glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &replace);
  EXPECT_EQ(replace, GL_TRUE);
  GLfloat replace_f = -1.f;
  glGetTexEnvfv(GL_POINT_SPRITE, GL_COORD_REPLACE, &replace_f);
  EXPECT_EQ(replace_f, 1.f);
  glActiveTexture(GL_TEXTURE0);
  glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &replace);
  EXPECT_EQ(replace, GL_FALSE);
  point(10.f, 10.f, 4.f);  // unit 0 is the textured one: not replaced
  EXPECT_EQ(count_pixels(texel(3, 0)), 16);
}

TEST_F(PointSpriteTest, PointSmoothIsIgnored) {
  sprites_on();
  glEnable(GL_POINT_SMOOTH);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  point(10.f, 10.f, 4.f);
  EXPECT_EQ(drawn_pixels(), 16);
  EXPECT_TRUE(near_rgba(pixel(8, 11), texel(0, 0)));  // a corner, fully covered
  EXPECT_TRUE(near_rgba(pixel(11, 8), texel(3, 3)));
}

TEST_F(PointSpriteTest, MipmapLevelFollowsTheSpriteSize) {
  // Levels of 8, 4, 2 and 1 texels in red, green, blue and white.
  const Rgba colours[] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
  for (int level = 0, size = 8; size >= 1; ++level, size /= 2) {
    const std::vector<uint8_t> t = solid_texels(size * size, colours[level]);
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, t.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  sprites_on();
  point(8.f, 8.f, 8.f);  // one texel per pixel: level 0
  point(24.f, 8.f, 4.f);  // two: level 1
  point(8.f, 24.f, 2.f);  // four: level 2
  EXPECT_EQ(count_pixels(colours[0]), 64);
  EXPECT_EQ(count_pixels(colours[1]), 16);
  EXPECT_EQ(count_pixels(colours[2]), 4);
}

TEST_F(PointSpriteTest, PolygonPointModeDrawsSprites) {
  sprites_on();
  glPointSize(4.f);
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glBegin(GL_TRIANGLES);
  glVertex2f(6.f, 6.f);
  glVertex2f(26.f, 6.f);
  glVertex2f(6.f, 26.f);
  glEnd();
  EXPECT_EQ(drawn_pixels(), 48);
  EXPECT_TRUE(near_rgba(pixel(4, 7), texel(0, 0)));
  EXPECT_TRUE(near_rgba(pixel(27, 4), texel(3, 3)));
  EXPECT_TRUE(near_rgba(pixel(4, 27), texel(0, 0)));
}

TEST_F(PointSpriteTest, BadValues) {
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, 2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexEnvf(GL_POINT_SPRITE, GL_COORD_REPLACE, -1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glTexEnvi(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint v = -1;
  glGetTexEnviv(GL_POINT_SPRITE, GL_TEXTURE_ENV_MODE, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(v, -1);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT + 2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glPointParameterf(GL_POINT_SPRITE_COORD_ORIGIN, 36001.5f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_UPPER_LEFT);
  glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &v);
  EXPECT_EQ(v, GL_FALSE);
  // A huge or NaN size still draws a bounded sprite.
  sprites_on();
  point(10.f, 10.f, 1e30f);
  EXPECT_EQ(drawn_pixels(), width() * height());
  clear_to(0, 0, 0, 0);
  glPointParameterf(GL_POINT_SIZE_MIN, 0.f);
  point(10.5f, 10.5f, 0.25f);  // under one pixel: kept to one
  EXPECT_EQ(drawn_pixels(), 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(PointSpriteTest, AttribGroups) {
  sprites_on();
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
  glPushAttrib(GL_POINT_BIT);
  glDisable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_POINT_SPRITE), GL_TRUE);
  GLint v = -1;
  glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &v);
  EXPECT_EQ(v, GL_TRUE);
  EXPECT_EQ(get_int(GL_POINT_SPRITE_COORD_ORIGIN), GL_LOWER_LEFT);
  // ENABLE_BIT: the enable only.
  glPushAttrib(GL_ENABLE_BIT);
  glDisable(GL_POINT_SPRITE);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_POINT_SPRITE), GL_TRUE);
  glGetTexEnviv(GL_POINT_SPRITE, GL_COORD_REPLACE, &v);
  EXPECT_EQ(v, GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
