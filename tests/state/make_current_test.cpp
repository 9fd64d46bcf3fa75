// State that a context takes from its first drawable, and keeps across later bindings.
#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

using MakeCurrentTest = GlTest;

TEST_F(MakeCurrentTest, RebindingKeepsViewportScissorAndBuffers) {
  glViewport(1, 2, 3, 4);
  glScissor(5, 6, 7, 8);
  glDrawBuffer(GL_FRONT_LEFT);
  glReadBuffer(GL_FRONT_LEFT);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  surface_->release();
  ASSERT_TRUE(surface_->make_current());
  EXPECT_EQ(get_ints(GL_VIEWPORT, 4), (std::vector<GLint>{1, 2, 3, 4}));
  EXPECT_EQ(get_ints(GL_SCISSOR_BOX, 4), (std::vector<GLint>{5, 6, 7, 8}));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), GL_FRONT_LEFT);
  EXPECT_EQ(get_int(GL_READ_BUFFER), GL_FRONT_LEFT);
}

TEST_F(MakeCurrentTest, DrawBufferErrors) {
  if (get_bool(GL_DOUBLEBUFFER)) GTEST_SKIP() << "needs a single-buffered surface";
  glDrawBuffer(GL_BACK);  // no back buffer
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDrawBuffer(GL_AUX0);  // no aux buffers
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glDrawBuffer(GL_TEXTURE_2D);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glReadBuffer(GL_NONE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), GL_FRONT);
  EXPECT_EQ(get_int(GL_READ_BUFFER), GL_FRONT);
}

}  // namespace
}  // namespace pineda::test
