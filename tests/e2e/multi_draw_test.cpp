// glMultiDrawArrays, glMultiDrawElements, glDrawRangeElements.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class MultiDrawTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glVertexPointer(2, GL_FLOAT, 0, kQuads);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColor3f(1, 1, 1);
  }
  // Three quads: 4x4 at (0,0), 2x2 at (10,10), 3x3 at (20,20).
  static constexpr GLfloat kQuads[] = {0, 0, 4, 0, 4, 4, 0, 4, 10, 10, 12, 10, 12, 12, 10, 12,
                                       20, 20, 23, 20, 23, 23, 20, 23};
};

TEST_F(MultiDrawTest, MultiDrawArraysDrawsEachRange) {
  const GLint first[] = {0, 8};
  const GLsizei count[] = {4, 4};
  glMultiDrawArrays(GL_QUADS, first, count, 2);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 16 + 9);
  EXPECT_EQ(pixel(11, 11), (Rgba{0, 0, 0, 0}));
  glMultiDrawArraysEXT(GL_QUADS, first + 1, count, 0);  // nothing
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(MultiDrawTest, MultiDrawElementsDrawsEachList) {
  const GLubyte a[] = {4, 5, 6, 7};
  const GLubyte b[] = {8, 9, 10, 11};
  const void* indices[] = {a, b};
  const GLsizei count[] = {4, 4};
  glMultiDrawElements(GL_QUADS, count, GL_UNSIGNED_BYTE, indices, 2);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 4 + 9);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(MultiDrawTest, ErrorsDrawNothing) {
  const GLint first[] = {0, 8};
  const GLsizei bad_count[] = {4, -1};
  glMultiDrawArrays(GL_QUADS, first, bad_count, 2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const GLsizei count[] = {4, 4};
  glMultiDrawArrays(GL_QUADS, first, count, -1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glMultiDrawArrays(GL_POLYGON + 1, first, count, 2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  const GLubyte a[] = {0, 1, 2, 3};
  const void* indices[] = {a, a};
  glMultiDrawElements(GL_QUADS, count, GL_FLOAT, indices, 2);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDrawRangeElements(GL_QUADS, 3, 2, 4, GL_UNSIGNED_BYTE, a);  // end < start
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDrawRangeElements(GL_QUADS, 0, 3, -4, GL_UNSIGNED_BYTE, a);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDrawRangeElementsEXT(GL_QUADS, 0, 3, 4, GL_DOUBLE, a);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  glDrawRangeElements(GL_QUADS, 0, 3, 4, GL_UNSIGNED_BYTE, a);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 16);
}

TEST_F(MultiDrawTest, CompiledIntoDisplayLists) {
  const GLint first[] = {4, 8};
  const GLsizei count[] = {4, 4};
  const GLubyte a[] = {0, 1, 2, 3};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMultiDrawArrays(GL_QUADS, first, count, 2);
  glDrawRangeElements(GL_QUADS, 0, 3, 4, GL_UNSIGNED_BYTE, a);
  glEndList();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 0);
  glCallList(list);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 16 + 4 + 9);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
