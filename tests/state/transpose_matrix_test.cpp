// GL 1.3 transpose matrices: glLoad/MultTransposeMatrix{f,d} and the TRANSPOSE_*_MATRIX gets.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <array>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

using Mat = std::array<double, 16>;

// Row-major: element (row r, column c) at r * 4 + c.
constexpr Mat kRows = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};

Mat transposed(const Mat& m) {
  Mat t;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) t[c * 4 + r] = m[r * 4 + c];
  return t;
}

Mat get_matrix(GLenum pname) {
  Mat m;
  m.fill(-7777);
  glGetDoublev(pname, m.data());
  return m;
}

class TransposeMatrixTest : public GlTest {
 protected:
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
};

TEST_F(TransposeMatrixTest, LoadTransposeStoresTheRowsAsColumns) {
  glLoadTransposeMatrixd(kRows.data());
  EXPECT_EQ(get_matrix(GL_MODELVIEW_MATRIX), transposed(kRows));
  EXPECT_EQ(get_matrix(GL_TRANSPOSE_MODELVIEW_MATRIX), kRows);

  GLfloat rows_f[16];
  for (int i = 0; i < 16; ++i) rows_f[i] = GLfloat(kRows[i] * 0.5);
  glLoadTransposeMatrixf(rows_f);
  const auto column_major = get_floats(GL_MODELVIEW_MATRIX, 16);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(column_major[c * 4 + r], rows_f[r * 4 + c]) << r << "," << c;
  const auto transposed_f = get_floats(GL_TRANSPOSE_MODELVIEW_MATRIX, 16);
  for (int i = 0; i < 16; ++i) EXPECT_EQ(transposed_f[i], rows_f[i]) << i;
}

TEST_F(TransposeMatrixTest, MultTransposeEqualsMultOfTheTranspose) {
  // A translation by (5, 6, 7) written row by row: its last column holds the offset.
  const Mat translate_rows = {1, 0, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1};
  glLoadIdentity();
  glScaled(2, 3, 4);
  glMultTransposeMatrixd(translate_rows.data());
  const Mat expected = {2, 0, 0, 0, 0, 3, 0, 0, 0, 0, 4, 0, 10, 18, 28, 1};
  EXPECT_EQ(get_matrix(GL_MODELVIEW_MATRIX), expected);

  GLfloat translate_f[16];
  for (int i = 0; i < 16; ++i) translate_f[i] = GLfloat(translate_rows[i]);
  glLoadIdentity();
  glScaled(2, 3, 4);
  glMultTransposeMatrixf(translate_f);
  EXPECT_EQ(get_matrix(GL_MODELVIEW_MATRIX), expected);
}

TEST_F(TransposeMatrixTest, ProjectionAndTextureStacksOfTheActiveUnit) {
  glMatrixMode(GL_PROJECTION);
  glLoadTransposeMatrixd(kRows.data());
  EXPECT_EQ(get_matrix(GL_TRANSPOSE_PROJECTION_MATRIX), kRows);
  EXPECT_EQ(get_matrix(GL_PROJECTION_MATRIX), transposed(kRows));

  glActiveTexture(GL_TEXTURE2);
  glMatrixMode(GL_TEXTURE);
  glLoadTransposeMatrixd(kRows.data());
  EXPECT_EQ(get_matrix(GL_TRANSPOSE_TEXTURE_MATRIX), kRows);
  glActiveTexture(GL_TEXTURE0);
  const Mat identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_EQ(get_matrix(GL_TRANSPOSE_TEXTURE_MATRIX), identity);
  EXPECT_EQ(get_matrix(GL_TRANSPOSE_MODELVIEW_MATRIX), identity);
}

TEST_F(TransposeMatrixTest, ArbAliasesAndDisplayLists) {
  glLoadTransposeMatrixdARB(kRows.data());
  EXPECT_EQ(get_matrix(GL_TRANSPOSE_MODELVIEW_MATRIX), kRows);
  glLoadIdentity();

  Mat rows = kRows;
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glLoadTransposeMatrixd(rows.data());
  glEndList();
  rows.fill(0);  // the list holds its own copy
  const Mat identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_EQ(get_matrix(GL_MODELVIEW_MATRIX), identity);  // compiled, not executed
  glCallList(list);
  EXPECT_EQ(get_matrix(GL_TRANSPOSE_MODELVIEW_MATRIX), kRows);
  glDeleteLists(list, 1);
}

TEST_F(TransposeMatrixTest, TransposedMatrixTransformsVertices) {
  // glOrtho(0, w, 0, h, -1, 1) given row by row: the quad at (8..24) lands on those pixels.
  const double w = width(), h = height();
  const Mat ortho_rows = {2 / w, 0, 0, -1, 0, 2 / h, 0, -1, 0, 0, -1, 0, 0, 0, 0, 1};
  glMatrixMode(GL_PROJECTION);
  glLoadTransposeMatrixd(ortho_rows.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  clear_to(0, 0, 0, 0);
  glColor3f(1, 1, 1);
  glRectf(8, 8, 24, 24);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 16 * 16);
  EXPECT_EQ(pixel(8, 8), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(pixel(7, 8), (Rgba{0, 0, 0, 0}));
}

}  // namespace
}  // namespace pineda::test
