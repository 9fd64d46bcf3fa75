// Storage of light, light-model and material parameters.
#include <cmath>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class LightingStateTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
  std::vector<GLfloat> light(GLenum l, GLenum pname, int n) {
    std::vector<GLfloat> v(n, -99.f);
    glGetLightfv(l, pname, v.data());
    return v;
  }
  std::vector<GLfloat> material(GLenum face, GLenum pname, int n) {
    std::vector<GLfloat> v(n, -99.f);
    glGetMaterialfv(face, pname, v.data());
    return v;
  }
};

using Floats = std::vector<GLfloat>;

TEST_F(LightingStateTest, InitialLights) {
  EXPECT_EQ(light(GL_LIGHT0, GL_AMBIENT, 4), (Floats{0, 0, 0, 1}));
  EXPECT_EQ(light(GL_LIGHT0, GL_DIFFUSE, 4), (Floats{1, 1, 1, 1}));
  EXPECT_EQ(light(GL_LIGHT0, GL_SPECULAR, 4), (Floats{1, 1, 1, 1}));
  EXPECT_EQ(light(GL_LIGHT1, GL_DIFFUSE, 4), (Floats{0, 0, 0, 1}));
  EXPECT_EQ(light(GL_LIGHT1, GL_SPECULAR, 4), (Floats{0, 0, 0, 1}));
  EXPECT_EQ(light(GL_LIGHT3, GL_POSITION, 4), (Floats{0, 0, 1, 0}));
  EXPECT_EQ(light(GL_LIGHT3, GL_SPOT_DIRECTION, 3), (Floats{0, 0, -1}));
  EXPECT_EQ(light(GL_LIGHT3, GL_SPOT_EXPONENT, 1), (Floats{0}));
  EXPECT_EQ(light(GL_LIGHT3, GL_SPOT_CUTOFF, 1), (Floats{180}));
  EXPECT_EQ(light(GL_LIGHT3, GL_CONSTANT_ATTENUATION, 1), (Floats{1}));
  EXPECT_EQ(light(GL_LIGHT3, GL_LINEAR_ATTENUATION, 1), (Floats{0}));
  EXPECT_EQ(light(GL_LIGHT3, GL_QUADRATIC_ATTENUATION, 1), (Floats{0}));
}

TEST_F(LightingStateTest, InitialMaterial) {
  for (GLenum face : {GL_FRONT, GL_BACK}) {
    EXPECT_EQ(material(face, GL_AMBIENT, 4), (Floats{0.2f, 0.2f, 0.2f, 1}));
    EXPECT_EQ(material(face, GL_DIFFUSE, 4), (Floats{0.8f, 0.8f, 0.8f, 1}));
    EXPECT_EQ(material(face, GL_SPECULAR, 4), (Floats{0, 0, 0, 1}));
    EXPECT_EQ(material(face, GL_EMISSION, 4), (Floats{0, 0, 0, 1}));
    EXPECT_EQ(material(face, GL_SHININESS, 1), (Floats{0}));
  }
}

TEST_F(LightingStateTest, PositionIsTransformedByTheModelviewAtCallTime) {
  glTranslatef(1, 2, 3);
  glRotatef(90, 0, 0, 1);
  const GLfloat point[4] = {1, 0, 0, 1};
  glLightfv(GL_LIGHT1, GL_POSITION, point);
  const Floats p = light(GL_LIGHT1, GL_POSITION, 4);
  EXPECT_NEAR(p[0], 1, 1e-6);
  EXPECT_NEAR(p[1], 3, 1e-6);
  EXPECT_NEAR(p[2], 3, 1e-6);
  EXPECT_NEAR(p[3], 1, 1e-6);
  // A direction (w = 0) is rotated but not translated.
  const GLfloat direction[4] = {1, 0, 0, 0};
  glLightfv(GL_LIGHT2, GL_POSITION, direction);
  const Floats d = light(GL_LIGHT2, GL_POSITION, 4);
  EXPECT_NEAR(d[0], 0, 1e-6);
  EXPECT_NEAR(d[1], 1, 1e-6);
  EXPECT_NEAR(d[2], 0, 1e-6);
  EXPECT_NEAR(d[3], 0, 1e-6);
  // Later modelview changes do not move it.
  glLoadIdentity();
  EXPECT_NEAR(light(GL_LIGHT1, GL_POSITION, 4)[1], 3, 1e-6);
}

TEST_F(LightingStateTest, SpotDirectionIsTransformedByTheUpperThreeByThree) {
  glTranslatef(5, 5, 5);
  glRotatef(90, 0, 1, 0);
  const GLfloat dir[3] = {0, 0, -1};
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, dir);
  const Floats d = light(GL_LIGHT0, GL_SPOT_DIRECTION, 3);
  EXPECT_NEAR(d[0], -1, 1e-6);
  EXPECT_NEAR(d[1], 0, 1e-6);
  EXPECT_NEAR(d[2], 0, 1e-6);
}

TEST_F(LightingStateTest, ScalarAndVectorParameters) {
  glLightf(GL_LIGHT4, GL_SPOT_EXPONENT, 12.5f);
  glLighti(GL_LIGHT4, GL_SPOT_CUTOFF, 45);
  glLightf(GL_LIGHT4, GL_CONSTANT_ATTENUATION, 2.f);
  glLightf(GL_LIGHT4, GL_LINEAR_ATTENUATION, 0.5f);
  glLightf(GL_LIGHT4, GL_QUADRATIC_ATTENUATION, 0.25f);
  const GLfloat ambient[4] = {0.1f, 0.2f, 0.3f, 0.4f};
  glLightfv(GL_LIGHT4, GL_AMBIENT, ambient);
  const GLint diffuse[4] = {2147483647, 0, 2147483647, 2147483647};
  glLightiv(GL_LIGHT4, GL_DIFFUSE, diffuse);
  EXPECT_EQ(light(GL_LIGHT4, GL_SPOT_EXPONENT, 1), (Floats{12.5f}));
  EXPECT_EQ(light(GL_LIGHT4, GL_SPOT_CUTOFF, 1), (Floats{45}));
  EXPECT_EQ(light(GL_LIGHT4, GL_CONSTANT_ATTENUATION, 1), (Floats{2}));
  EXPECT_EQ(light(GL_LIGHT4, GL_LINEAR_ATTENUATION, 1), (Floats{0.5f}));
  EXPECT_EQ(light(GL_LIGHT4, GL_QUADRATIC_ATTENUATION, 1), (Floats{0.25f}));
  EXPECT_EQ(light(GL_LIGHT4, GL_AMBIENT, 4), (Floats{0.1f, 0.2f, 0.3f, 0.4f}));
  const Floats d = light(GL_LIGHT4, GL_DIFFUSE, 4);
  EXPECT_FLOAT_EQ(d[0], 1.f);
  EXPECT_NEAR(d[1], 0.f, 1e-6);
  // Light colours are not clamped.
  const GLfloat bright[4] = {2, -1, 0, 1};
  glLightfv(GL_LIGHT4, GL_SPECULAR, bright);
  EXPECT_EQ(light(GL_LIGHT4, GL_SPECULAR, 4), (Floats{2, -1, 0, 1}));
}

TEST_F(LightingStateTest, ParameterErrorsChangeNothing) {
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 129.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, -1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 91.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, -1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, -0.5f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glLightf(GL_LIGHT0 + 1, GL_POSITION, 3.f);  // a vector parameter: (3, 0, 0, 0), as in Mesa
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(light(GL_LIGHT0 + 1, GL_POSITION, 4), (Floats{3, 0, 0, 0}));
  glLightf(GL_LIGHT0 + 8, GL_SPOT_EXPONENT, 1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glLightf(GL_LIGHT0, 0x1234, 1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(light(GL_LIGHT0, GL_SPOT_EXPONENT, 1), (Floats{0}));
  EXPECT_EQ(light(GL_LIGHT0, GL_SPOT_CUTOFF, 1), (Floats{180}));
  EXPECT_EQ(light(GL_LIGHT0, GL_LINEAR_ATTENUATION, 1), (Floats{0}));
  GLfloat v[4] = {5, 5, 5, 5};
  glGetLightfv(GL_LIGHT0, 0x1234, v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(v[0], 5.f);
}

TEST_F(LightingStateTest, LightModel) {
  const GLfloat ambient[4] = {0.5f, 0.25f, 0.125f, 1.f};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  glLightModelf(GL_LIGHT_MODEL_TWO_SIDE, 1.f);
  EXPECT_EQ(get_floats(GL_LIGHT_MODEL_AMBIENT, 4), (Floats{0.5f, 0.25f, 0.125f, 1.f}));
  EXPECT_EQ(get_bool(GL_LIGHT_MODEL_LOCAL_VIEWER), GL_TRUE);
  EXPECT_EQ(get_bool(GL_LIGHT_MODEL_TWO_SIDE), GL_TRUE);
  glLightModeli(0x1234, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_floats(GL_LIGHT_MODEL_AMBIENT, 4)[0], 0.5f);
  glLightModelf(GL_LIGHT_MODEL_AMBIENT, 0.75f);  // a vector parameter: (0.75, 0, 0, 0), as in Mesa
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(get_floats(GL_LIGHT_MODEL_AMBIENT, 4), (Floats{0.75f, 0, 0, 0}));
}

TEST_F(LightingStateTest, MaterialFaces) {
  const GLfloat red[4] = {1, 0, 0, 1};
  const GLfloat green[4] = {0, 1, 0, 0.5f};
  glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
  glMaterialfv(GL_BACK, GL_EMISSION, green);
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 64.f);
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, green);
  EXPECT_EQ(material(GL_FRONT, GL_DIFFUSE, 4), (Floats{1, 0, 0, 1}));
  EXPECT_EQ(material(GL_BACK, GL_DIFFUSE, 4), (Floats{0.8f, 0.8f, 0.8f, 1}));
  EXPECT_EQ(material(GL_BACK, GL_EMISSION, 4), (Floats{0, 1, 0, 0.5f}));
  EXPECT_EQ(material(GL_FRONT, GL_EMISSION, 4), (Floats{0, 0, 0, 1}));
  EXPECT_EQ(material(GL_FRONT, GL_SHININESS, 1), (Floats{64}));
  EXPECT_EQ(material(GL_BACK, GL_SHININESS, 1), (Floats{64}));
  EXPECT_EQ(material(GL_FRONT, GL_SPECULAR, 4), (Floats{0, 1, 0, 0.5f}));
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
  EXPECT_EQ(material(GL_FRONT, GL_AMBIENT, 4), (Floats{0, 1, 0, 0.5f}));
  EXPECT_EQ(material(GL_FRONT, GL_DIFFUSE, 4), (Floats{0, 1, 0, 0.5f}));
  glMaterialf(GL_FRONT, GL_SHININESS, 129.f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glMaterialfv(GL_LEFT, GL_DIFFUSE, red);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(material(GL_FRONT, GL_SHININESS, 1), (Floats{64}));
  glMaterialf(GL_FRONT, GL_DIFFUSE, 0.5f);  // a vector parameter: (0.5, 0, 0, 0), as in Mesa
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(material(GL_FRONT, GL_DIFFUSE, 4), (Floats{0.5f, 0, 0, 0}));
  GLfloat v = 3;
  glGetMaterialfv(GL_FRONT_AND_BACK, GL_SHININESS, &v);  // the query needs one face
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(v, 3.f);
}

TEST_F(LightingStateTest, ColorIndexesAreKeptPerFace) {
  const GLfloat indexes[3] = {2, 5, 9};
  glMaterialfv(GL_FRONT, GL_COLOR_INDEXES, indexes);
  EXPECT_EQ(material(GL_FRONT, GL_COLOR_INDEXES, 3), (Floats{2, 5, 9}));
  EXPECT_EQ(material(GL_BACK, GL_COLOR_INDEXES, 3), (Floats{0, 1, 1}));
  GLint i[3] = {0, 0, 0};
  glGetMaterialiv(GL_FRONT, GL_COLOR_INDEXES, i);
  EXPECT_EQ(i[2], 9);
}

TEST_F(LightingStateTest, MaterialInsideBeginEndIsAllowed) {
  const GLfloat blue[4] = {0, 0, 1, 1};
  glBegin(GL_POINTS);
  glMaterialfv(GL_FRONT, GL_EMISSION, blue);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(material(GL_FRONT, GL_EMISSION, 4), (Floats{0, 0, 1, 1}));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// GL 1.1 spec 2.13.3: with COLOR_MATERIAL enabled the selected material properties take the
// current colour whenever it changes, and keep it after COLOR_MATERIAL is disabled.
TEST_F(LightingStateTest, ColorMaterialUpdatesTheStoredMaterial) {
  glColorMaterial(GL_FRONT, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glColor4f(0.25f, 0.5f, 0.75f, 1.f);
  EXPECT_EQ(material(GL_FRONT, GL_DIFFUSE, 4), (Floats{0.25f, 0.5f, 0.75f, 1.f}));
  EXPECT_EQ(material(GL_BACK, GL_DIFFUSE, 4), (Floats{0.8f, 0.8f, 0.8f, 1}));
  EXPECT_EQ(material(GL_FRONT, GL_AMBIENT, 4), (Floats{0.2f, 0.2f, 0.2f, 1}));
  glDisable(GL_COLOR_MATERIAL);
  glColor4f(1, 0, 0, 1);
  EXPECT_EQ(material(GL_FRONT, GL_DIFFUSE, 4), (Floats{0.25f, 0.5f, 0.75f, 1.f}));
}

TEST_F(LightingStateTest, EnablingColorMaterialAppliesTheCurrentColour) {
  glColor4f(0.5f, 0.25f, 0.125f, 0.5f);
  glColorMaterial(GL_BACK, GL_EMISSION);
  glEnable(GL_COLOR_MATERIAL);
  EXPECT_EQ(material(GL_BACK, GL_EMISSION, 4), (Floats{0.5f, 0.25f, 0.125f, 0.5f}));
  EXPECT_EQ(material(GL_FRONT, GL_EMISSION, 4), (Floats{0, 0, 0, 1}));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(LightingStateTest, IntegerQueriesMapColoursAndRoundTheRest) {
  const GLfloat diffuse[4] = {0.5f, 1.f, 0.f, 2.f};
  glLightfv(GL_LIGHT1, GL_DIFFUSE, diffuse);
  const GLfloat position[4] = {1.4f, -2.6f, 3.f, 1.f};
  glLightfv(GL_LIGHT1, GL_POSITION, position);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 44.5f);
  GLint v[4] = {7, 7, 7, 7};
  glGetLightiv(GL_LIGHT1, GL_DIFFUSE, v);
  EXPECT_NEAR(double(v[0]), 0.5 * kIntColorScale, 1.0);
  EXPECT_EQ(v[1], 2147483647);
  EXPECT_EQ(v[2], 0);
  EXPECT_EQ(v[3], 2147483647);  // clamped to 1 before mapping
  glGetLightiv(GL_LIGHT1, GL_POSITION, v);
  EXPECT_EQ(v[0], 1);
  EXPECT_EQ(v[1], -3);
  EXPECT_EQ(v[2], 3);
  EXPECT_EQ(v[3], 1);
  glGetLightiv(GL_LIGHT1, GL_SPOT_CUTOFF, v);
  EXPECT_EQ(v[0], 45);  // rounded half away from zero
  glMaterialf(GL_BACK, GL_SHININESS, 10.4f);
  glGetMaterialiv(GL_BACK, GL_SHININESS, v);
  EXPECT_EQ(v[0], 10);
  glGetMaterialiv(GL_FRONT, GL_AMBIENT, v);
  EXPECT_NEAR(double(v[0]), 0.2 * kIntColorScale, 512.0);
  EXPECT_EQ(v[3], 2147483647);
  GLint untouched[4] = {5, 5, 5, 5};
  glGetLightiv(GL_LIGHT0, 0x1234, untouched);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetMaterialiv(GL_FRONT_AND_BACK, GL_AMBIENT, untouched);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(untouched[0], 5);
}

}  // namespace
}  // namespace pineda::test
