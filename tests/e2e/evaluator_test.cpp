// Evaluators (GL 1.1 section 5.1): maps evaluated as Bernstein polynomials into vertices,
// meshes over grids, the queries, errors, display lists and attribute groups.
#include <climits>
#include <cmath>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

constexpr Rgba kWhite{255, 255, 255, 255};

double binomial(int n, int k) {
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

double bernstein(int n, int i, double t) { return binomial(n, i) * std::pow(t, i) * std::pow(1 - t, n - i); }

class EvaluatorTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glColor3f(1, 1, 1);
  }
  // A line of vertices from (x0, y) to (x1, y) as u goes over [0, 1].
  static void linear_map1(float x0, float x1, float y) {
    const GLfloat points[6] = {x0, y, 0, x1, y, 0};
    glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, points);
    glEnable(GL_MAP1_VERTEX_3);
  }
  // The plane z = 0 over [x0, x1] x [y0, y1] as (u, v) goes over [0, 1]^2.
  static void plane_map2(float x0, float y0, float x1, float y1) {
    const GLfloat points[12] = {x0, y0, 0, x0, y1, 0, x1, y0, 0, x1, y1, 0};  // (i, j): u index i, v index j
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, points);
    glEnable(GL_MAP2_VERTEX_3);
  }
};

TEST_F(EvaluatorTest, LinearMap1DrawnByEvalMesh1Points) {
  linear_map1(2.5f, 26.5f, 4.5f);
  glMapGrid1f(8, 0, 1);
  glEvalMesh1(GL_POINT, 0, 8);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(count_pixels(kWhite), 9);
  for (int i = 0; i <= 8; ++i) EXPECT_TRUE(near_rgba(pixel(2 + 3 * i, 4), kWhite)) << "point " << i;
  clear_to(0, 0, 0, 0);
  glEvalMesh1(GL_POINT, 2, 3);  // a part of the grid
  EXPECT_EQ(count_pixels(kWhite), 2);
  EXPECT_TRUE(near_rgba(pixel(8, 4), kWhite));
  EXPECT_TRUE(near_rgba(pixel(11, 4), kWhite));
}

TEST_F(EvaluatorTest, EvalMesh1LineIsALineStrip) {
  const GLfloat points[9] = {2, 3, 0, 30, 12, 0, 4, 29, 0};  // a quadratic curve
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 3, points);
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(6, 0, 1);
  glEvalMesh1(GL_LINE, 0, 6);
  const std::vector<uint8_t> evaluated = read_all();
  clear_to(0, 0, 0, 0);
  glBegin(GL_LINE_STRIP);
  for (int i = 0; i <= 6; ++i) {
    const double u = i / 6.0;
    double p[2] = {0, 0};
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 2; ++c) p[c] += bernstein(2, k, u) * points[3 * k + c];
    glVertex2d(p[0], p[1]);
  }
  glEnd();
  EXPECT_EQ(evaluated, read_all());
  EXPECT_GT(count_pixels(kWhite), 30);
}

TEST_F(EvaluatorTest, Map2ColoursAtPixelCentresMatchBernstein) {
  plane_map2(0.5f, 0.5f, 31.5f, 31.5f);  // grid point (i, j) lands on pixel centre (i, j)
  // A biquadratic colour map (uorder 3, vorder 2) with ustride 8 and vstride 4.
  GLfloat colors[3 * 8];
  const GLfloat control[3][2][4] = {{{1, 0, 0, 1}, {0, 1, 0, 1}},
                                    {{0, 0, 1, 0.5f}, {1, 1, 0, 0.25f}},
                                    {{0.2f, 0.9f, 0.4f, 1}, {0.7f, 0.1f, 0.6f, 0}}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 2; ++j)
      for (int c = 0; c < 4; ++c) colors[8 * i + 4 * j + c] = control[i][j][c];
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 8, 3, 0, 1, 4, 2, colors);
  glEnable(GL_MAP2_COLOR_4);
  glMapGrid2f(31, 0, 1, 31, 0, 1);
  glEvalMesh2(GL_POINT, 0, 31, 0, 31);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const std::vector<uint8_t> evaluated = read_all();
  // The same points drawn with the Bernstein polynomial's colours computed here.
  clear_to(0, 0, 0, 0);
  glBegin(GL_POINTS);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const double u = x / 31.0, v = y / 31.0;
      double color[4] = {0, 0, 0, 0};
      for (int c = 0; c < 4; ++c)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 2; ++j) color[c] += bernstein(2, i, u) * bernstein(1, j, v) * control[i][j][c];
      glColor4dv(color);
      glVertex2d(x + 0.5, y + 0.5);
    }
  glEnd();
  EXPECT_EQ(evaluated, read_all());
  // In bytes at two corners, where the map takes its corner control points.
  EXPECT_TRUE(near_rgba({evaluated[0], evaluated[1], evaluated[2], evaluated[3]}, {255, 0, 0, 255}));
  const size_t top_right = (size_t(31) * 32 + 31) * 4;
  EXPECT_TRUE(near_rgba({evaluated[top_right], evaluated[top_right + 1], evaluated[top_right + 2],
                         evaluated[top_right + 3]},
                        {to_byte(0.7f), to_byte(0.1f), to_byte(0.6f), 0}));
}

TEST_F(EvaluatorTest, EvalMesh2FillAndLineEqualImmediateMode) {
  const GLfloat corner[4][4] = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 1}};
  plane_map2(1, 2, 30, 29);
  glMap2f(GL_MAP2_COLOR_4, 0, 1, 8, 2, 0, 1, 4, 2, &corner[0][0]);
  glEnable(GL_MAP2_COLOR_4);
  glMapGrid2f(4, 0, 1, 3, 0, 1);
  auto vertex = [&](int i, int j) {
    const double u = i / 4.0, v = j / 3.0;
    double color[4] = {0, 0, 0, 0};
    for (int c = 0; c < 4; ++c)
      color[c] = (1 - u) * (1 - v) * corner[0][c] + (1 - u) * v * corner[1][c] + u * (1 - v) * corner[2][c] +
                 u * v * corner[3][c];
    glColor4dv(color);
    glVertex2d(1 + 29 * u, 2 + 27 * v);
  };
  glEvalMesh2(GL_FILL, 0, 4, 0, 3);
  const std::vector<uint8_t> fill = read_all();
  clear_to(0, 0, 0, 0);
  for (int j = 0; j < 3; ++j) {
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= 4; ++i) {
      vertex(i, j);
      vertex(i, j + 1);
    }
    glEnd();
  }
  EXPECT_EQ(fill, read_all());
  clear_to(0, 0, 0, 0);
  glEvalMesh2(GL_LINE, 0, 4, 0, 3);
  const std::vector<uint8_t> lines = read_all();
  clear_to(0, 0, 0, 0);
  for (int j = 0; j <= 3; ++j) {
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= 4; ++i) vertex(i, j);
    glEnd();
  }
  for (int i = 0; i <= 4; ++i) {
    glBegin(GL_LINE_STRIP);
    for (int j = 0; j <= 3; ++j) vertex(i, j);
    glEnd();
  }
  EXPECT_EQ(lines, read_all());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(EvaluatorTest, EvalCoordUsesEvaluatedValuesWithoutChangingCurrentOnes) {
  const GLfloat vertices[8] = {0, 0, 0, 1, 64, 32, 0, 2};  // (x/w, y/w) from (0, 0) to (32, 16)
  const GLfloat colors[8] = {1, 0, 0, 1, 0, 0, 1, 0};
  const GLfloat tex2[4] = {5, 6, 7, 8};
  const GLfloat tex3[6] = {0, 1, 2, 4, 5, 6};
  glMap1f(GL_MAP1_VERTEX_4, 0, 4, 4, 2, vertices);
  glMap1f(GL_MAP1_COLOR_4, 0, 4, 4, 2, colors);
  glMap1f(GL_MAP1_TEXTURE_COORD_2, 0, 4, 2, 2, tex2);
  glMap1f(GL_MAP1_TEXTURE_COORD_3, 0, 4, 3, 2, tex3);
  for (GLenum cap : {GL_MAP1_VERTEX_4, GL_MAP1_COLOR_4, GL_MAP1_TEXTURE_COORD_2, GL_MAP1_TEXTURE_COORD_3})
    glEnable(cap);
  glColor4f(0.25f, 0.5f, 0.75f, 1);
  glTexCoord4f(9, 9, 9, 9);
  GLfloat buffer[64];
  glFeedbackBuffer(64, GL_4D_COLOR_TEXTURE, buffer);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS);
  glEvalCoord1f(1);  // u' = 1/4
  glVertex2f(3, 3);  // a plain vertex between them takes the current values
  glEnd();
  ASSERT_EQ(glRenderMode(GL_RENDER), 2 * 13);
  // The evaluated vertex: (16, 8, 0, 1.25) projected; colour and texture coordinates of u' = 1/4.
  // Only TEXTURE_COORD_3, the largest enabled texture map, is evaluated.
  const double w = 1.25;
  const float expected[13] = {GL_POINT_TOKEN, float(16 / w), float(8 / w), 0.5f, float(w),
                              0.75f, 0, 0.25f, 0.75f,
                              1, 2, 3, 1};
  for (int i = 0; i < 13; ++i) EXPECT_NEAR(buffer[i], expected[i], 1e-5) << "value " << i;
  const float plain[13] = {GL_POINT_TOKEN, 3, 3, 0.5f, 1, 0.25f, 0.5f, 0.75f, 1, 9, 9, 9, 9};
  for (int i = 0; i < 13; ++i) EXPECT_NEAR(buffer[13 + i], plain[i], 1e-5) << "value " << i;
  GLfloat color[4], tex[4];
  glGetFloatv(GL_CURRENT_COLOR, color);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, tex);
  EXPECT_EQ(color[0], 0.25f);
  EXPECT_EQ(color[2], 0.75f);
  EXPECT_EQ(tex[0], 9.f);
  EXPECT_EQ(tex[3], 9.f);
}

TEST_F(EvaluatorTest, EvalPointReachesTheGridEndExactly) {
  const GLfloat points[6] = {0, 0, 0, 30, 0, 0};
  glMap1f(GL_MAP1_VERTEX_3, 0.1f, 0.7f, 3, 2, points);
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(3, 0.1f, 0.7f);
  GLfloat buffer[8];
  glFeedbackBuffer(8, GL_2D, buffer);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_POINTS);
  glEvalPoint1(3);  // u = u2 exactly, so the last control point exactly
  glEvalPoint1(0);
  glEnd();
  ASSERT_EQ(glRenderMode(GL_RENDER), 6);
  EXPECT_EQ(buffer[1], 30.f);
  EXPECT_EQ(buffer[4], 0.f);
}

TEST_F(EvaluatorTest, NoVertexMapNoVertexAndNothingOutsideBeginEnd) {
  const GLfloat points[6] = {4.5f, 4.5f, 0, 8.5f, 4.5f, 0};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, points);
  glBegin(GL_POINTS);
  glEvalCoord1f(0);  // MAP1_VERTEX_3 is disabled
  glEnd();
  glEnable(GL_MAP1_VERTEX_3);
  glEvalCoord1f(1);  // outside glBegin/glEnd: as glVertex there, no effect
  glMapGrid1f(1, 0, 1);
  glEvalPoint1(0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(count_pixels(kWhite), 0);
  glDisable(GL_MAP1_VERTEX_3);
  glEvalMesh1(GL_POINT, 0, 1);
  EXPECT_EQ(count_pixels(kWhite), 0);
  glEnable(GL_MAP1_VERTEX_3);
  glBegin(GL_POINTS);
  glEvalCoord1d(1);
  glEnd();
  EXPECT_EQ(count_pixels(kWhite), 1);
  EXPECT_TRUE(near_rgba(pixel(8, 4), kWhite));
}

class EvaluatorLightingTest : public EvaluatorTest {
 protected:
  void SetUp() override {
    EvaluatorTest::SetUp();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 32, 0, 32, -100, 100);
    glMatrixMode(GL_MODELVIEW);
    const GLfloat direction[4] = {0, 0, 1, 0}, white[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, direction);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, black);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, black);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, white);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
  }
  int lit_red() {
    glClear(GL_COLOR_BUFFER_BIT);
    glMapGrid2f(2, 0, 1, 2, 0, 1);
    glEvalMesh2(GL_FILL, 0, 2, 0, 2);
    return pixel(16, 16)[0];
  }
};

TEST_F(EvaluatorLightingTest, AutoNormalIsTheNormalizedCrossProductOfThePartials) {
  // p(u, v) = (32u, 32v, 24u): dp/du x dp/dv = (32, 0, 24) x (0, 32, 0) = (-768, 0, 1024),
  // normalized (-0.6, 0, 0.8): diffuse 0.8 from a light along +z.
  const GLfloat points[12] = {0, 0, 0, 0, 32, 0, 32, 0, 24, 32, 32, 24};
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, points);
  glEnable(GL_MAP2_VERTEX_3);
  glNormal3f(0, 0, 1);
  EXPECT_EQ(lit_red(), 255);  // without AUTO_NORMAL the current normal is used
  glEnable(GL_AUTO_NORMAL);
  EXPECT_EQ(lit_red(), to_byte(0.8));
  // It replaces an enabled normal map.
  const GLfloat normals[3] = {0, 0, 1};
  glMap2f(GL_MAP2_NORMAL, 0, 1, 3, 1, 0, 1, 3, 1, normals);
  glEnable(GL_MAP2_NORMAL);
  EXPECT_EQ(lit_red(), to_byte(0.8));
  glDisable(GL_AUTO_NORMAL);
  EXPECT_EQ(lit_red(), 255);
  // A 4-component map: the normal of the projected surface (x/w, y/w, z/w).
  const GLfloat homogeneous[16] = {0, 0, 0, 2, 0, 64, 0, 2, 64, 0, 48, 2, 64, 64, 48, 2};
  glMap2f(GL_MAP2_VERTEX_4, 0, 1, 8, 2, 0, 1, 4, 2, homogeneous);
  glEnable(GL_MAP2_VERTEX_4);
  glDisable(GL_MAP2_NORMAL);
  glEnable(GL_AUTO_NORMAL);
  EXPECT_EQ(lit_red(), to_byte(0.8));
  GLfloat current[3];
  glGetFloatv(GL_CURRENT_NORMAL, current);
  EXPECT_EQ(current[2], 1.f);  // evaluation does not change the current normal
}

TEST_F(EvaluatorLightingTest, AutoNormalFollowsTheOrientationOfUAndV) {
  // u along -x: dp/du x dp/dv = (-32, 0, 0) x (0, 32, 0) points along -z, away from the light.
  const GLfloat points[12] = {32, 0, 0, 32, 32, 0, 0, 0, 0, 0, 32, 0};
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, points);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  EXPECT_EQ(lit_red(), 0);
}

TEST_F(EvaluatorLightingTest, DegenerateSurfaceHasAZeroNormal) {
  // Every control point on one line: dp/du x dp/dv = 0, so no diffuse light (alpha stays 1).
  const GLfloat points[12] = {4.5f, 4.5f, 0, 4.5f, 4.5f, 0, 28.5f, 4.5f, 0, 28.5f, 4.5f, 0};
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, points);
  glEnable(GL_MAP2_VERTEX_3);
  glEnable(GL_AUTO_NORMAL);
  glMapGrid2f(2, 0, 1, 1, 0, 1);
  glEvalMesh2(GL_POINT, 0, 2, 0, 1);
  EXPECT_EQ(count_pixels({0, 0, 0, 255}), 3);
  EXPECT_TRUE(near_rgba(pixel(16, 4), {0, 0, 0, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(EvaluatorTest, NonFiniteDomainDrawsNothing) {
  const GLfloat points[6] = {4.5f, 4.5f, 0, 8.5f, 4.5f, 0};
  glMap1f(GL_MAP1_VERTEX_3, NAN, 1, 3, 2, points);  // accepted: u1 != u2
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(4, 0, INFINITY);
  glEvalMesh1(GL_LINE, 0, 4);
  glEvalMesh1(GL_POINT, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(count_pixels(kWhite), 0);
}

TEST_F(EvaluatorTest, GetMapReturnsTheCopiedControlPoints) {
  GLdouble colors[15] = {0.5, 1, 2.5, -2.5, 99, 3, 4, 5, 6, 99, 7, 8, 9, 10, 99};  // stride 5
  glMap1d(GL_MAP1_COLOR_4, -1, 3, 5, 3, colors);
  colors[0] = 42;  // the points were copied at the call
  GLdouble coeff[12];
  glGetMapdv(GL_MAP1_COLOR_4, GL_COEFF, coeff);
  const GLdouble expected[12] = {0.5, 1, 2.5, -2.5, 3, 4, 5, 6, 7, 8, 9, 10};
  for (int i = 0; i < 12; ++i) EXPECT_EQ(coeff[i], expected[i]) << i;
  GLint icoeff[12];
  glGetMapiv(GL_MAP1_COLOR_4, GL_COEFF, icoeff);
  EXPECT_EQ(icoeff[0], 1);  // rounded to the nearest integer, halves away from zero
  EXPECT_EQ(icoeff[2], 3);
  EXPECT_EQ(icoeff[3], -3);
  GLint order = 0;
  glGetMapiv(GL_MAP1_COLOR_4, GL_ORDER, &order);
  EXPECT_EQ(order, 3);
  GLfloat domain[2];
  glGetMapfv(GL_MAP1_COLOR_4, GL_DOMAIN, domain);
  EXPECT_EQ(domain[0], -1.f);
  EXPECT_EQ(domain[1], 3.f);

  // Map2: uorder 2, vorder 3, ustride 9, vstride 3; COEFF lists u-major.
  GLfloat normals[18];
  for (int i = 0; i < 18; ++i) normals[i] = float(i);
  glMap2f(GL_MAP2_NORMAL, 0, 2, 9, 2, 1, 5, 3, 3, normals);
  GLfloat n[18];
  glGetMapfv(GL_MAP2_NORMAL, GL_COEFF, n);
  for (int i = 0; i < 18; ++i) EXPECT_EQ(n[i], float(i)) << i;
  GLint orders[2];
  glGetMapiv(GL_MAP2_NORMAL, GL_ORDER, orders);
  EXPECT_EQ(orders[0], 2);
  EXPECT_EQ(orders[1], 3);
  GLdouble domain2[4];
  glGetMapdv(GL_MAP2_NORMAL, GL_DOMAIN, domain2);
  EXPECT_EQ(domain2[0], 0.0);
  EXPECT_EQ(domain2[1], 2.0);
  EXPECT_EQ(domain2[2], 1.0);
  EXPECT_EQ(domain2[3], 5.0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(EvaluatorTest, InitialMaps) {
  GLfloat v[4] = {-1, -1, -1, -1};
  glGetMapfv(GL_MAP1_INDEX, GL_COEFF, v);
  EXPECT_EQ(v[0], 1.f);
  EXPECT_EQ(v[1], -1.f);  // one value only
  glGetMapfv(GL_MAP2_VERTEX_4, GL_COEFF, v);
  EXPECT_EQ(v[0], 0.f);
  EXPECT_EQ(v[3], 1.f);
  glGetMapfv(GL_MAP1_NORMAL, GL_COEFF, v);
  EXPECT_EQ(v[2], 1.f);
  glGetMapfv(GL_MAP2_COLOR_4, GL_COEFF, v);
  EXPECT_EQ(v[0], 1.f);
  EXPECT_EQ(v[3], 1.f);
  GLint orders[2] = {0, 0};
  glGetMapiv(GL_MAP2_TEXTURE_COORD_2, GL_ORDER, orders);
  EXPECT_EQ(orders[0], 1);
  EXPECT_EQ(orders[1], 1);
  GLfloat domain[4];
  glGetMapfv(GL_MAP2_TEXTURE_COORD_2, GL_DOMAIN, domain);
  EXPECT_EQ(domain[1], 1.f);
  EXPECT_EQ(domain[3], 1.f);
  GLint max_order = 0;
  glGetIntegerv(GL_MAX_EVAL_ORDER, &max_order);
  EXPECT_EQ(max_order, 30);
}

TEST_F(EvaluatorTest, Errors) {
  GLfloat points[4 * 31] = {};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 31, points);  // order > MAX_EVAL_ORDER
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 0, points);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glMap1f(GL_MAP1_VERTEX_3, 1, 1, 3, 2, points);  // u1 == u2
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glMap1f(GL_MAP1_VERTEX_4, 0, 1, 3, 2, points);  // stride < 4 components
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glMap1f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, points);  // a MAP2 target for glMap1
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glMap2f(GL_TEXTURE_2D, 0, 1, 3, 2, 0, 1, 6, 2, points);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 6, 31, points);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 0, 1, 2, 2, points);  // vstride < 3
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 2, 2, 2, 6, 2, points);  // v1 == v2
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glActiveTexture(GL_TEXTURE1);  // maps belong to texture unit 0
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, points);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glActiveTexture(GL_TEXTURE0);
  GLint order = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  EXPECT_EQ(order, 1);  // no failed call changed the map

  glMapGrid1f(0, 0, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glMapGrid2d(1, 0, 1, -1, 0, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glEvalMesh1(GL_FILL, 0, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glEvalMesh2(GL_LINE_STRIP, 0, 1, 0, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetMapiv(GL_MAP1_VERTEX_3, GL_MAP1_GRID_DOMAIN, &order);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetMapiv(GL_TEXTURE_1D, GL_ORDER, &order);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));

  glBegin(GL_POINTS);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, points);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glEvalMesh1(GL_POINT, 0, 1);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glMapGrid1f(2, 0, 1);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);  // the commands that specify vertices are allowed
  glEvalCoord1f(0);
  glEvalCoord2f(0, 0);
  glEvalPoint1(0);
  glEvalPoint2(0, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(EvaluatorTest, HugeMeshIsOutOfMemoryNotAHang) {
  linear_map1(0, 32, 4.5f);
  glEvalMesh1(GL_POINT, INT_MIN, INT_MAX);
  EXPECT_EQ(glGetError(), GLenum(GL_OUT_OF_MEMORY));
  plane_map2(0, 0, 32, 32);
  glEvalMesh2(GL_FILL, INT_MIN, INT_MAX, INT_MIN, INT_MAX);
  EXPECT_EQ(glGetError(), GLenum(GL_OUT_OF_MEMORY));
  EXPECT_EQ(count_pixels(kWhite), 0);
}

TEST_F(EvaluatorTest, DisplayListsReplayTheMapsAndMeshes) {
  GLfloat points[6] = {2.5f, 4.5f, 0, 26.5f, 4.5f, 0};
  glNewList(1, GL_COMPILE);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 2, points);
  glEnable(GL_MAP1_VERTEX_3);
  glMapGrid1f(8, 0, 1);
  glEvalMesh1(GL_POINT, 0, 8);
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 40, points);  // an error recorded when the list runs
  glEndList();
  points[1] = 20.5f;  // the list holds the points as they were at compile time
  GLint order = 0, segments = 0;
  glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, &segments);
  EXPECT_EQ(order, 1);  // GL_COMPILE executes nothing
  EXPECT_EQ(segments, 1);
  EXPECT_EQ(glIsEnabled(GL_MAP1_VERTEX_3), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glCallList(1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(count_pixels(kWhite), 9);
  for (int i = 0; i <= 8; ++i) EXPECT_TRUE(near_rgba(pixel(2 + 3 * i, 4), kWhite)) << "point " << i;
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, &segments);
  EXPECT_EQ(segments, 8);
  // EvalCoord and EvalPoint inside a compiled Begin/End.
  clear_to(0, 0, 0, 0);
  glNewList(2, GL_COMPILE);
  glBegin(GL_POINTS);
  glEvalCoord1f(0.5f);
  glEvalPoint1(8);
  glEnd();
  glEndList();
  glCallList(2);
  EXPECT_EQ(count_pixels(kWhite), 2);
  EXPECT_TRUE(near_rgba(pixel(14, 4), kWhite));
  EXPECT_TRUE(near_rgba(pixel(26, 4), kWhite));
  // Map2 with a copied control net.
  clear_to(0, 0, 0, 0);
  GLfloat net[12] = {4.5f, 6.5f, 0, 4.5f, 6.5f, 0, 4.5f, 6.5f, 0, 4.5f, 6.5f, 0};
  glNewList(3, GL_COMPILE);
  glMap2f(GL_MAP2_VERTEX_3, 0, 1, 6, 2, 0, 1, 3, 2, net);
  glEndList();
  net[0] = 30;
  glCallList(3);
  glEnable(GL_MAP2_VERTEX_3);
  glBegin(GL_POINTS);
  glEvalCoord2f(0, 0);
  glEnd();
  EXPECT_EQ(count_pixels(kWhite), 1);
  EXPECT_TRUE(near_rgba(pixel(4, 6), kWhite));
}

TEST_F(EvaluatorTest, EnablesGridsAndAttribGroups) {
  EXPECT_EQ(glIsEnabled(GL_AUTO_NORMAL), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_MAP2_TEXTURE_COORD_3), GL_FALSE);
  GLfloat domain1[2], domain2[4];
  GLint segments2[2];
  glGetFloatv(GL_MAP1_GRID_DOMAIN, domain1);
  EXPECT_EQ(domain1[0], 0.f);
  EXPECT_EQ(domain1[1], 1.f);
  glMapGrid1d(5, -2, 6);
  glMapGrid2f(3, 1, 2, 7, 3, 4);
  glGetFloatv(GL_MAP1_GRID_DOMAIN, domain1);
  EXPECT_EQ(domain1[0], -2.f);
  EXPECT_EQ(domain1[1], 6.f);
  glGetFloatv(GL_MAP2_GRID_DOMAIN, domain2);
  EXPECT_EQ(domain2[0], 1.f);
  EXPECT_EQ(domain2[1], 2.f);
  EXPECT_EQ(domain2[2], 3.f);
  EXPECT_EQ(domain2[3], 4.f);
  glGetIntegerv(GL_MAP2_GRID_SEGMENTS, segments2);
  EXPECT_EQ(segments2[0], 3);
  EXPECT_EQ(segments2[1], 7);

  glEnable(GL_MAP1_COLOR_4);
  glPushAttrib(GL_EVAL_BIT);
  glEnable(GL_AUTO_NORMAL);
  glEnable(GL_MAP2_TEXTURE_COORD_3);
  glDisable(GL_MAP1_COLOR_4);
  glMapGrid1f(9, 0, 1);
  GLboolean on = GL_FALSE;
  glGetBooleanv(GL_MAP2_TEXTURE_COORD_3, &on);
  EXPECT_EQ(on, GL_TRUE);
  const GLfloat tc[1] = {3};
  glMap1f(GL_MAP1_TEXTURE_COORD_1, 0, 1, 1, 1, tc);  // maps are not in EVAL_BIT
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_AUTO_NORMAL), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_MAP2_TEXTURE_COORD_3), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_MAP1_COLOR_4), GL_TRUE);
  GLint segments = 0;
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, &segments);
  EXPECT_EQ(segments, 5);
  GLfloat coeff = 0;
  glGetMapfv(GL_MAP1_TEXTURE_COORD_1, GL_COEFF, &coeff);
  EXPECT_EQ(coeff, 3.f);

  glPushAttrib(GL_ENABLE_BIT);  // the enables, not the grids
  glEnable(GL_AUTO_NORMAL);
  glDisable(GL_MAP1_COLOR_4);
  glMapGrid1f(9, 0, 1);
  glPopAttrib();
  EXPECT_EQ(glIsEnabled(GL_AUTO_NORMAL), GL_FALSE);
  EXPECT_EQ(glIsEnabled(GL_MAP1_COLOR_4), GL_TRUE);
  glGetIntegerv(GL_MAP1_GRID_SEGMENTS, &segments);
  EXPECT_EQ(segments, 9);
}

}  // namespace
}  // namespace pineda::test
