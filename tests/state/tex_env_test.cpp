// glTexEnv and glGetTexEnv.
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class TexEnvTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
  GLint mode() {
    GLint m = -1;
    glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &m);
    return m;
  }
};

TEST_F(TexEnvTest, InitialValues) {
  EXPECT_EQ(mode(), GL_MODULATE);
  GLfloat c[4] = {-1, -1, -1, -1};
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
  for (float v : c) EXPECT_EQ(v, 0.f);
}

TEST_F(TexEnvTest, EveryModeReadsBack) {
  for (GLint m : {GL_REPLACE, GL_DECAL, GL_BLEND, GL_MODULATE}) {
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, m);
    EXPECT_EQ(mode(), m);
    GLfloat f = 0;
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &f);
    EXPECT_EQ(f, GLfloat(m));
  }
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  EXPECT_EQ(mode(), GL_DECAL);
  const GLint blend = GL_BLEND;
  glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &blend);
  EXPECT_EQ(mode(), GL_BLEND);
}

TEST_F(TexEnvTest, ColorIsClampedAndMapsToIntegers) {
  const GLfloat c[4] = {0.5f, -1.f, 2.f, 0.25f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
  GLfloat f[4];
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
  EXPECT_EQ(f[0], 0.5f);
  EXPECT_EQ(f[1], 0.f);
  EXPECT_EQ(f[2], 1.f);
  EXPECT_EQ(f[3], 0.25f);
  GLint i[4];
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, i);
  EXPECT_NEAR(double(i[0]), 0.5 * kIntColorScale, 1.0);
  EXPECT_EQ(i[1], 0);
  EXPECT_EQ(i[2], 2147483647);
  // Integer colours map [-2^31, 2^31 - 1] onto [-1, 1].
  const GLint ic[4] = {2147483647, 0, 1073741823, 2147483647};
  glTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, ic);
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, f);
  EXPECT_FLOAT_EQ(f[0], 1.f);
  EXPECT_NEAR(f[1], 0.f, 1e-6);
  EXPECT_NEAR(f[2], 0.5f, 1e-6);
}

TEST_F(TexEnvTest, ErrorsChangeNothing) {
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_NEAREST);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexEnvi(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexEnvi(GL_TEXTURE_ENV, 0x1234, GL_REPLACE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexEnvf(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 0.5f);  // a vector parameter: (0.5, 0, 0, 0), as in Mesa
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLfloat env_color[4];
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color);
  EXPECT_EQ(std::vector<GLfloat>(env_color, env_color + 4), (std::vector<GLfloat>{0.5f, 0, 0, 0}));
  EXPECT_EQ(mode(), GL_DECAL);
  GLint m = 99;
  glGetTexEnviv(GL_TEXTURE_2D, GL_TEXTURE_ENV_MODE, &m);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(m, 99);
  GLfloat f = 99.f;
  glGetTexEnvfv(GL_TEXTURE_ENV, 0x1234, &f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(f, 99.f);
}

}  // namespace
}  // namespace pineda::test
