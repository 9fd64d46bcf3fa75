// Matrix stacks: every matrix command against hand-computed column-major matrices.
#include <array>
#include <cmath>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

using Mat = std::array<double, 16>;  // column-major, as GL stores it

constexpr Mat kIdentity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

Mat multiply(const Mat& a, const Mat& b) {
  Mat r{};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row)
      for (int k = 0; k < 4; ++k) r[c * 4 + row] += a[k * 4 + row] * b[c * 4 + k];
  return r;
}

Mat get_matrix(GLenum pname) {
  Mat m;
  glGetDoublev(pname, m.data());
  return m;
}

void expect_matrix(const Mat& actual, const Mat& expected, double tolerance = 1e-6) {
  for (int i = 0; i < 16; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "element " << i;
}

class MatrixTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
};

TEST_F(MatrixTest, LoadMatrixReadsBack) {
  const GLfloat m[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  glLoadMatrixf(m);
  const auto f = get_floats(GL_MODELVIEW_MATRIX, 16);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(f[i], m[i]);
  const GLdouble d[16] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6};
  glLoadMatrixd(d);
  const Mat got = get_matrix(GL_MODELVIEW_MATRIX);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(got[i], d[i]);  // kept in double precision
  glLoadIdentity();
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), kIdentity, 0);
}

TEST_F(MatrixTest, MultMatrixPostMultiplies) {
  const Mat a = {1, 2, 0, 0, 0, 1, 3, 0, 4, 0, 1, 0, 5, 6, 7, 1};
  const Mat b = {2, 0, 1, 0, 0, 3, 0, 1, 1, 1, 1, 0, 0, 2, 0, 1};
  glLoadMatrixd(a.data());
  glMultMatrixd(b.data());
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), multiply(a, b));
  GLfloat bf[16];
  for (int i = 0; i < 16; ++i) bf[i] = GLfloat(b[i]);
  glLoadMatrixd(a.data());
  glMultMatrixf(bf);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), multiply(a, b));
}

TEST_F(MatrixTest, Translate) {
  glTranslatef(1, 2, 3);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1});
  glTranslated(-1, 0.5, 0);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 2.5, 3, 1});
}

TEST_F(MatrixTest, Scale) {
  glScaled(2, 3, 4);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), {2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1});
  glScalef(0.5f, 1, -1);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), {1, 0, 0, 0, 0, 3, 0, 0, 0, 0, -4, 0, 0, 0, 0, 1});
}

TEST_F(MatrixTest, RotateAboutEachAxis) {
  glRotatef(90, 0, 0, 1);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), {0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
  glLoadIdentity();
  glRotated(90, 1, 0, 0);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), {1, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1});
  glLoadIdentity();
  glRotated(90, 0, 1, 0);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), {0, 0, -1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1});
}

TEST_F(MatrixTest, RotateNormalizesTheAxis) {
  glRotated(30, 0, 0, 5);
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), {c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1});
}

TEST_F(MatrixTest, RotateAboutAnArbitraryAxis) {
  // GL 1.1 spec 2.10.2: R = uu^T + cos(a)(I - uu^T) + sin(a)S.
  const double a = 40 * M_PI / 180, x = 1 / std::sqrt(3.0), y = x, z = x;
  const double c = std::cos(a), s = std::sin(a), t = 1 - c;
  const Mat expected = {t * x * x + c,     t * x * y + s * z, t * x * z - s * y, 0,
                        t * x * y - s * z, t * y * y + c,     t * y * z + s * x, 0,
                        t * x * z + s * y, t * y * z - s * x, t * z * z + c,     0,
                        0,                 0,                 0,                 1};
  glRotated(40, 1, 1, 1);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), expected, 1e-12);
}

TEST_F(MatrixTest, Frustum) {
  glMatrixMode(GL_PROJECTION);
  glFrustum(0, 2, -1, 3, 1, 5);
  // 2n/(r-l), 2n/(t-b), (r+l)/(r-l), (t+b)/(t-b), -(f+n)/(f-n), -2fn/(f-n)
  expect_matrix(get_matrix(GL_PROJECTION_MATRIX), {1, 0, 0, 0, 0, 0.5, 0, 0, 1, 0.5, -1.5, -1, 0, 0, -2.5, 0});
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), kIdentity, 0);
}

TEST_F(MatrixTest, Ortho) {
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, 4, 0, 2, -1, 3);
  expect_matrix(get_matrix(GL_PROJECTION_MATRIX), {0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -0.5, 0, -1, -1, -0.5, 1});
}

TEST_F(MatrixTest, OrthoMultipliesTheCurrentMatrix) {
  glMatrixMode(GL_PROJECTION);
  glScaled(2, 2, 2);
  glOrtho(-1, 1, -1, 1, -1, 1);
  expect_matrix(get_matrix(GL_PROJECTION_MATRIX), {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, -2, 0, 0, 0, 0, 1});
}

TEST_F(MatrixTest, FrustumAndOrthoErrorsChangeNothing) {
  glMatrixMode(GL_PROJECTION);
  glFrustum(-1, 1, -1, 1, 0, 10);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glFrustum(-1, 1, -1, 1, -1, 10);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glFrustum(-1, 1, -1, 1, 1, -10);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glFrustum(1, 1, -1, 1, 1, 10);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glFrustum(-1, 1, -1, 1, 2, 2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glOrtho(0, 0, -1, 1, -1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glOrtho(0, 1, 2, 2, -1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glOrtho(0, 1, 0, 1, 3, 3);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  expect_matrix(get_matrix(GL_PROJECTION_MATRIX), kIdentity, 0);
}

TEST_F(MatrixTest, CompositionOrder) {
  glTranslated(10, 0, 0);
  glRotated(90, 0, 0, 1);
  glScaled(2, 2, 2);
  // T * R * S: the point (1, 0, 0) goes to S: (2,0,0), R: (0,2,0), T: (10,2,0).
  const Mat m = get_matrix(GL_MODELVIEW_MATRIX);
  EXPECT_NEAR(m[0] * 1 + m[12], 10, 1e-12);
  EXPECT_NEAR(m[1] * 1 + m[13], 2, 1e-12);
  EXPECT_NEAR(m[2] * 1 + m[14], 0, 1e-12);
}

TEST_F(MatrixTest, ModesSelectTheirOwnStack) {
  glMatrixMode(GL_PROJECTION);
  glTranslated(1, 0, 0);
  glMatrixMode(GL_TEXTURE);
  glScaled(3, 3, 3);
  glMatrixMode(GL_MODELVIEW);
  glTranslated(0, 0, 7);
  EXPECT_EQ(get_matrix(GL_PROJECTION_MATRIX)[12], 1.0);
  EXPECT_EQ(get_matrix(GL_TEXTURE_MATRIX)[0], 3.0);
  EXPECT_EQ(get_matrix(GL_MODELVIEW_MATRIX)[14], 7.0);
  EXPECT_EQ(get_matrix(GL_MODELVIEW_MATRIX)[0], 1.0);
}

TEST_F(MatrixTest, PushCopiesAndPopRestores) {
  glTranslated(1, 2, 3);
  glPushMatrix();
  EXPECT_EQ(get_int(GL_MODELVIEW_STACK_DEPTH), 2);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1}, 0);
  glScaled(5, 5, 5);
  glPopMatrix();
  EXPECT_EQ(get_int(GL_MODELVIEW_STACK_DEPTH), 1);
  expect_matrix(get_matrix(GL_MODELVIEW_MATRIX), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 2, 3, 1}, 0);
}

struct StackCase {
  GLenum mode, depth_pname, max_pname, matrix_pname;
};

class MatrixStackLimitTest : public GlTest, public ::testing::WithParamInterface<StackCase> {};

TEST_P(MatrixStackLimitTest, OverflowAndUnderflowAtTheReportedDepth) {
  const StackCase c = GetParam();
  glMatrixMode(c.mode);
  const GLint max = get_int(c.max_pname);
  ASSERT_GE(max, 2);
  glPopMatrix();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
  EXPECT_EQ(get_int(c.depth_pname), 1);
  for (GLint i = 1; i < max; ++i) {
    glTranslated(i, 0, 0);
    glPushMatrix();
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << "push to depth " << i + 1;
  }
  EXPECT_EQ(get_int(c.depth_pname), max);
  glLoadIdentity();
  glScaled(2, 2, 2);
  glPushMatrix();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_OVERFLOW));
  EXPECT_EQ(get_int(c.depth_pname), max);
  EXPECT_EQ(get_matrix(c.matrix_pname)[0], 2.0);  // the failed push changed nothing
  for (GLint i = max - 1; i >= 1; --i) {
    glPopMatrix();
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    // Translations accumulate: the matrix pushed at depth i had sum 1..i.
    EXPECT_EQ(get_matrix(c.matrix_pname)[12], double(i * (i + 1) / 2)) << i;
  }
  EXPECT_EQ(get_int(c.depth_pname), 1);
  glPopMatrix();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
}

INSTANTIATE_TEST_SUITE_P(
    Stacks, MatrixStackLimitTest,
    ::testing::Values(
        StackCase{GL_MODELVIEW, GL_MODELVIEW_STACK_DEPTH, GL_MAX_MODELVIEW_STACK_DEPTH, GL_MODELVIEW_MATRIX},
        StackCase{GL_PROJECTION, GL_PROJECTION_STACK_DEPTH, GL_MAX_PROJECTION_STACK_DEPTH, GL_PROJECTION_MATRIX},
        StackCase{GL_TEXTURE, GL_TEXTURE_STACK_DEPTH, GL_MAX_TEXTURE_STACK_DEPTH, GL_TEXTURE_MATRIX}));

}  // namespace
}  // namespace pineda::test
