// Fixed-function lighting of a known vertex against the GL 1.1 lighting equation.
#include <algorithm>
#include <cmath>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

struct V3 {
  double x, y, z;
};
V3 normalize(V3 v) {
  const double l = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  return {v.x / l, v.y / l, v.z / l};
}
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

class LightingTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {16, 16, 24, 0}; }
  void SetUp() override {
    GlTest::SetUp();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    clear_to(0, 0, 0, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
  }
  // A screen-filling quad with one normal: every pixel has the colour of its vertices
  // (for a directional light and an infinite viewer the colour does not depend on position).
  void quad(V3 n) {
    glNormal3d(n.x, n.y, n.z);
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
  }
};

TEST_F(LightingTest, DefaultLightAndMaterial) {
  quad({0, 0, 1});
  // emission 0 + 0.2 * 0.2 (model ambient) + light 0: ambient 0, diffuse 1 * 0.8 * (n.l = 1),
  // specular 0 (material specular 0).
  const int c = to_byte(0.2 * 0.2 + 0.8);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {c, c, c, 255}, 1));
}

TEST_F(LightingTest, FullEquationWithOneDirectionalLight) {
  const GLfloat mat_ambient[4] = {0.3f, 0.2f, 0.1f, 1}, mat_diffuse[4] = {0.6f, 0.5f, 0.4f, 0.7f},
                mat_specular[4] = {0.5f, 0.5f, 0.5f, 1}, mat_emission[4] = {0.05f, 0.1f, 0.0f, 1};
  const GLfloat shininess = 10;
  const GLfloat model_ambient[4] = {0.1f, 0.2f, 0.3f, 1};
  const GLfloat light_ambient[4] = {0.2f, 0.2f, 0.2f, 1}, light_diffuse[4] = {0.9f, 0.8f, 0.7f, 1},
                light_specular[4] = {1, 1, 1, 1};
  const V3 light_dir = normalize({1, 2, 3});
  const GLfloat position[4] = {1, 2, 3, 0};
  glMaterialfv(GL_FRONT, GL_AMBIENT, mat_ambient);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, mat_diffuse);
  glMaterialfv(GL_FRONT, GL_SPECULAR, mat_specular);
  glMaterialfv(GL_FRONT, GL_EMISSION, mat_emission);
  glMaterialf(GL_FRONT, GL_SHININESS, shininess);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model_ambient);
  glLightfv(GL_LIGHT0, GL_AMBIENT, light_ambient);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, light_diffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, light_specular);
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  const V3 n = normalize({0.2, -0.1, 1});
  quad(n);
  const double n_dot_l = std::max(dot(n, light_dir), 0.0);
  const V3 h = normalize({light_dir.x, light_dir.y, light_dir.z + 1});  // infinite viewer: + (0, 0, 1)
  const double spec = n_dot_l > 0 ? std::pow(std::max(dot(n, h), 0.0), shininess) : 0;
  Rgba expected;
  for (int i = 0; i < 3; ++i) {
    const double c = mat_emission[i] + mat_ambient[i] * model_ambient[i] + mat_ambient[i] * light_ambient[i] +
                     n_dot_l * mat_diffuse[i] * light_diffuse[i] + spec * mat_specular[i] * light_specular[i];
    expected[i] = to_byte(std::clamp(c, 0.0, 1.0));
  }
  expected[3] = to_byte(mat_diffuse[3]);
  EXPECT_TRUE(near_rgba(pixel(8, 8), expected, 1));
}

TEST_F(LightingTest, LightPositionUsesTheModelviewAtSpecification) {
  // The light is specified through a rotation that turns +x into +z, then the modelview is
  // reset: the light shines along +z in eye space, straight onto the normal (0, 0, 1).
  glRotatef(-90, 0, 1, 0);
  const GLfloat position[4] = {1, 0, 0, 0};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLoadIdentity();
  quad({0, 0, 1});
  const int c = to_byte(0.04 + 0.8);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {c, c, c, 255}, 1));
  // A normal facing away from the light gets only the ambient terms.
  clear_to(0, 0, 0, 0);
  quad({0, 0, -1});
  const int a = to_byte(0.04);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {a, a, a, 255}, 1));
}

TEST_F(LightingTest, PositionalLightWithAttenuation) {
  // A light 2 units in front of a vertex at the centre of pixel (8, 8).
  const GLfloat position[4] = {0, 0, 2, 1};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightf(GL_LIGHT0, GL_CONSTANT_ATTENUATION, 0.5f);
  glLightf(GL_LIGHT0, GL_LINEAR_ATTENUATION, 0.75f);
  const GLfloat model_ambient[4] = {0, 0, 0, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model_ambient);
  const double v = 0.0625;  // NDC of the centre of pixel 8 on a 16-pixel axis
  glBegin(GL_POINTS);
  glNormal3f(0, 0, 1);
  glVertex3d(v, v, 0);
  glEnd();
  const double d = std::sqrt(2 * v * v + 4), n_dot_l = 2 / d;
  const double attenuation = 1.0 / (0.5 + 0.75 * d);
  const int c = to_byte(attenuation * 0.8 * n_dot_l);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {c, c, c, 255}, 1));
}

TEST_F(LightingTest, ColorMaterialTracksTheCurrentColour) {
  glEnable(GL_COLOR_MATERIAL);  // GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE
  glColor4f(0.5f, 0.25f, 1.0f, 0.6f);
  quad({0, 0, 1});
  const double r = 0.5 * 0.2 + 0.5, g = 0.25 * 0.2 + 0.25, b = std::min(1.0 * 0.2 + 1.0, 1.0);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {to_byte(r), to_byte(g), to_byte(b), to_byte(0.6)}, 1));
}

TEST_F(LightingTest, TwoSidedLightingUsesTheBackMaterialForBackFaces) {
  glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
  const GLfloat back_diffuse[4] = {0, 1, 0, 1};
  glMaterialfv(GL_BACK, GL_DIFFUSE, back_diffuse);
  // Clockwise: a back face, lit with the reversed normal (0, 0, 1) against the light at +z.
  glNormal3f(0, 0, -1);
  glBegin(GL_QUADS);
  glVertex2f(-1, -1);
  glVertex2f(-1, 1);
  glVertex2f(1, 1);
  glVertex2f(1, -1);
  glEnd();
  const int a = to_byte(0.04);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {a, 255, a, 255}, 1));  // green 0.04 + 1, clamped
}

TEST_F(LightingTest, DisabledLightContributesNothing) {
  glDisable(GL_LIGHT0);
  quad({0, 0, 1});
  const int a = to_byte(0.04);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {a, a, a, 255}, 1));
}

TEST_F(LightingTest, NormalizeRescalesScaledNormals) {
  glScalef(1, 1, 0.25f);  // the normal matrix then lengthens (0, 0, 1) four times
  quad({0, 0, 1});
  const int unnormalized = pixel(8, 8)[0];
  EXPECT_EQ(unnormalized, 255);  // 0.04 + 0.8 * 4, clamped
  clear_to(0, 0, 0, 0);
  glEnable(GL_NORMALIZE);
  quad({0, 0, 1});
  const int c = to_byte(0.04 + 0.8);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {c, c, c, 255}, 1));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(LightingTest, MaterialKeepsTheColourAfterColorMaterialIsDisabled) {
  glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
  glEnable(GL_COLOR_MATERIAL);
  glColor3f(0, 1, 0);
  quad({0, 0, 1});
  glDisable(GL_COLOR_MATERIAL);
  glColor3f(1, 0, 0);  // no longer tracked
  clear_to(0, 0, 0, 0);
  quad({0, 0, 1});
  const int a = to_byte(0.04);
  EXPECT_TRUE(near_rgba(pixel(8, 8), {a, 255, a, 255}, 1));  // diffuse (0, 1, 0) stays
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(LightingTest, SpotlightExponentAndCutoff) {
  const GLfloat position[4] = {0, 0, 2, 1};
  const GLfloat direction[3] = {0, 0, -1};
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  glLightfv(GL_LIGHT0, GL_SPOT_DIRECTION, direction);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 30);
  glLightf(GL_LIGHT0, GL_SPOT_EXPONENT, 2);
  const GLfloat no_ambient[4] = {0, 0, 0, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, no_ambient);
  const double v = 0.0625;  // the centre of pixel (8, 8)
  glBegin(GL_POINTS);
  glNormal3f(0, 0, 1);
  glVertex3d(v, v, 0);
  glVertex3d(0.9375, 0.0625, 0);  // pixel (15, 8): about 25 degrees off the axis, inside
  glEnd();
  const double d = std::sqrt(2 * v * v + 4), cos_axis = 2 / d;
  const int c = to_byte(std::pow(cos_axis, 2) * 0.8 * cos_axis);  // spot * diffuse * (n.l = cos)
  EXPECT_TRUE(near_rgba(pixel(8, 8), {c, c, c, 255}, 1));
  const double x = 0.9375, y = 0.0625, d2 = std::sqrt(x * x + y * y + 4), cos2 = 2 / d2;
  const int c2 = to_byte(std::pow(cos2, 2) * 0.8 * cos2);
  EXPECT_TRUE(near_rgba(pixel(15, 8), {c2, c2, c2, 255}, 1));
  // Outside the cone: nothing but the (zero) ambient.
  clear_to(0, 0, 0, 0);
  glLightf(GL_LIGHT0, GL_SPOT_CUTOFF, 20);
  glBegin(GL_POINTS);
  glVertex3d(0.9375, 0.0625, 0);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(15, 8), {0, 0, 0, 255}, 1));
}

TEST_F(LightingTest, LocalViewerSpecular) {
  const GLfloat specular[4] = {1, 1, 1, 1};
  glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
  glMaterialf(GL_FRONT, GL_SHININESS, 8);
  const GLfloat zero[4] = {0, 0, 0, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, zero);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, zero);
  glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
  const GLfloat position[4] = {1, 0, 1, 0};  // directional, 45 degrees
  glLightfv(GL_LIGHT0, GL_POSITION, position);
  const double v = 0.0625;
  glBegin(GL_POINTS);
  glNormal3f(0, 0, 1);
  glVertex3d(v, v, 0);
  glEnd();
  // h = normalize(l + normalize(eye - p)), eye at the origin, p = (v, v, 0).
  const double lx = 1 / std::sqrt(2.0), lz = lx;
  const double el = std::sqrt(2 * v * v);
  double hx = lx - v / el, hy = -v / el, hz = lz;
  const double hl = std::sqrt(hx * hx + hy * hy + hz * hz);
  hx /= hl;
  hy /= hl;
  hz /= hl;
  const int c = to_byte(std::pow(hz, 8));
  EXPECT_TRUE(near_rgba(pixel(8, 8), {c, c, c, 255}, 1));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// GL 1.1 2.13.2: glMaterial between glBegin and glEnd applies to the vertices after it.
TEST_F(LightingTest, MaterialChangesInsideBeginEndApplyPerVertex) {
  glDisable(GL_LIGHT0);
  const GLfloat no_ambient[4] = {0, 0, 0, 1};
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, no_ambient);
  const GLfloat red[4] = {1, 0, 0, 1}, green[4] = {0, 1, 0, 1}, blue[4] = {0, 0, 1, 1};
  glMaterialfv(GL_FRONT, GL_EMISSION, red);
  glBegin(GL_POINTS);
  glVertex2f(-0.9375f, -0.9375f);  // pixel (0, 0)
  glMaterialfv(GL_FRONT, GL_EMISSION, green);
  glVertex2f(0.0625f, 0.0625f);  // pixel (8, 8)
  glMaterialfv(GL_FRONT, GL_EMISSION, red);
  glMaterialfv(GL_FRONT, GL_EMISSION, blue);  // two changes before one vertex: the last counts
  glVertex2f(0.9375f, 0.9375f);  // pixel (15, 15)
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(0, 0), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(8, 8), {0, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(15, 15), {0, 0, 255, 255}));
  GLfloat emission[4];
  glGetMaterialfv(GL_FRONT, GL_EMISSION, emission);
  EXPECT_EQ(emission[2], 1.f);  // the last material stays
  // The next primitive starts with it.
  clear_to(0, 0, 0, 0);
  glBegin(GL_POINTS);
  glVertex2f(0.0625f, 0.0625f);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(8, 8), {0, 0, 255, 255}));
}

}  // namespace
}  // namespace pineda::test
