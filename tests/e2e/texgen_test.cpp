// Texture coordinate generation (GL 1.5 section 2.11.4): object and eye linear planes, the
// normal and reflection maps, sphere map; state, errors, attributes.
#include <vector>

#include "tests/e2e/support/pixel_test.h"

namespace pineda::test {
namespace {

constexpr Rgba kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255};

class TexGenTest : public PixelTest {
 protected:
  void SetUp() override {
    PixelTest::SetUp();
    // Two texels: s < 0.5 red, s >= 0.5 green.
    const GLubyte texels[8] = {255, 0, 0, 255, 0, 255, 0, 255};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
  }
};

TEST_F(TexGenTest, ObjectLinear) {
  const GLfloat plane[4] = {1.f / 16, 0, 0, 0};  // s = x / 16
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_S);
  full_quad();
  EXPECT_TRUE(near_rgba(pixel(7, 3), kRed));
  EXPECT_TRUE(near_rgba(pixel(8, 3), kGreen));
  EXPECT_EQ(count_pixels(kGreen), 8 * 16);
}

TEST_F(TexGenTest, GeneratedCoordinatesGoThroughTheTextureMatrix) {
  const GLfloat plane[4] = {1.f / 16, 0, 0, 0};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, plane);
  glEnable(GL_TEXTURE_GEN_S);
  glMatrixMode(GL_TEXTURE);
  glTranslatef(0.25f, 0, 0);  // s = x / 16 + 1/4: green from x = 4
  glMatrixMode(GL_MODELVIEW);
  full_quad();
  EXPECT_EQ(count_pixels(kGreen), 12 * 16);
}

TEST_F(TexGenTest, EyeLinearPlaneIsFixedAtSpecification) {
  glTranslatef(-4, 0, 0);
  const GLfloat plane[4] = {1.f / 16, 0, 0, 0};  // eye plane: s = (x_eye + 4) / 16
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGenfv(GL_S, GL_EYE_PLANE, plane);
  glLoadIdentity();
  glEnable(GL_TEXTURE_GEN_S);
  full_quad();
  EXPECT_EQ(count_pixels(kGreen), 12 * 16);
  GLfloat stored[4];
  glGetTexGenfv(GL_S, GL_EYE_PLANE, stored);
  EXPECT_EQ(stored[0], 1.f / 16);
  EXPECT_EQ(stored[3], 0.25f);
}

TEST_F(TexGenTest, NormalMap) {
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glNormal3f(0.75f, 0, 0.6614f);  // s = n_x = 0.75
  full_quad();
  EXPECT_EQ(count_pixels(kGreen), 256);
  glNormal3f(0.25f, 0, 0.9682f);
  full_quad();
  EXPECT_EQ(count_pixels(kRed), 256);
}

// A point at eye (0, 0, -1), drawn at pixel (8, 8): the view direction is u = (0, 0, -1), and
// with n = (+-0.6, 0, 0.8) the reflection r = u - 2 n (n . u) is (+-0.96, 0, 0.28).
class TexGenOnAxisTest : public TexGenTest {
 protected:
  void SetUp() override {
    TexGenTest::SetUp();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-8.5, 7.5, -8.5, 7.5, -2, 2);
    glMatrixMode(GL_MODELVIEW);
  }
  Rgba point_with_normal(float nx) {
    glClear(GL_COLOR_BUFFER_BIT);
    glNormal3f(nx, 0, 0.8f);
    glBegin(GL_POINTS);
    glVertex3f(0, 0, -1);
    glEnd();
    return pixel(8, 8);
  }
};

TEST_F(TexGenOnAxisTest, ReflectionMap) {
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  EXPECT_TRUE(near_rgba(point_with_normal(0.6f), kGreen));  // s = 0.96
  EXPECT_TRUE(near_rgba(point_with_normal(-0.6f), kRed));   // s = -0.96
}

TEST_F(TexGenOnAxisTest, SphereMap) {
  // m = 2 sqrt(r_x^2 + r_y^2 + (r_z + 1)^2) = 3.2, s = r_x / m + 1/2.
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  EXPECT_TRUE(near_rgba(point_with_normal(0.6f), kGreen));  // s = 0.8
  EXPECT_TRUE(near_rgba(point_with_normal(-0.6f), kRed));   // s = 0.2
}

TEST_F(TexGenTest, ErrorsAndQueries) {
  GLint mode = 0;
  glGetTexGeniv(GL_T, GL_TEXTURE_GEN_MODE, &mode);
  EXPECT_EQ(mode, GL_EYE_LINEAR);
  GLdouble plane[4];
  glGetTexGendv(GL_S, GL_OBJECT_PLANE, plane);
  EXPECT_EQ(plane[0], 1.0);  // S's default plane is (1, 0, 0, 0)
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexGeni(GL_S + 4, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexGenf(GL_S, GL_OBJECT_PLANE, 2.f);  // a vector parameter: (2, 0, 0, 0), as in Mesa
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGetTexGendv(GL_S, GL_OBJECT_PLANE, plane);
  EXPECT_EQ(std::vector<GLdouble>(plane, plane + 4), (std::vector<GLdouble>{2, 0, 0, 0}));
  glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
  glGetTexGeniv(GL_R, GL_TEXTURE_GEN_MODE, &mode);
  EXPECT_EQ(mode, GL_REFLECTION_MAP);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(TexGenTest, PushPopTextureBit) {
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glPushAttrib(GL_TEXTURE_BIT);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
  glEnable(GL_TEXTURE_GEN_S);
  glPopAttrib();
  GLint mode = 0;
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &mode);
  EXPECT_EQ(mode, GL_OBJECT_LINEAR);
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_GEN_S));
}

}  // namespace
}  // namespace pineda::test
