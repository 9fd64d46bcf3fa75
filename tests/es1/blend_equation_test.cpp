// GL_EXT_blend_minmax and GL_OES_blend_subtract in OpenGL ES 1.1: glBlendEquationOES chooses
// MIN, MAX and the subtractions; exact 8-bit results.
#define GL_GLEXT_PROTOTYPES
#include <GLES/gl.h>
#include <GLES/glext.h>
#include <gtest/gtest.h>

#include "tests/es1/egl_context.h"

namespace pineda::es1_test {
namespace {

constexpr int kSize = 8;

class BlendEquation : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(ctx.ok()) << ctx.error();
    glViewport(0, 0, kSize, kSize);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_BYTE, 0, kQuad);
    glColor4ub(128, 128, 128, 255);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
  }
  int red_after(GLenum equation, GLubyte red) {
    glBlendEquationOES(equation);
    glColor4ub(red, red, red, 255);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    GLubyte p[4] = {};
    glReadPixels(kSize / 2, kSize / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
    return p[0];
  }
  static constexpr GLbyte kQuad[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
  Es1Context ctx{kSize, kSize};
};

TEST_F(BlendEquation, MinMaxAndSubtract) {
  EXPECT_EQ(red_after(GL_MIN_EXT, 64), 64);
  EXPECT_EQ(red_after(GL_MAX_EXT, 200), 200);
  EXPECT_EQ(red_after(GL_FUNC_SUBTRACT_OES, 250), 50);   // 250 - 200
  EXPECT_EQ(red_after(GL_FUNC_REVERSE_SUBTRACT_OES, 20), 30);  // 50 - 20
  GLint equation = 0;
  glGetIntegerv(GL_BLEND_EQUATION_OES, &equation);
  EXPECT_EQ(equation, GL_FUNC_REVERSE_SUBTRACT_OES);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(BlendEquation, SeparateForms) {
  glBlendFuncSeparateOES(GL_ONE, GL_ZERO, GL_ZERO, GL_ONE);
  glBlendEquationSeparateOES(GL_FUNC_ADD_OES, GL_MAX_EXT);
  GLint v = 0;
  glGetIntegerv(GL_BLEND_DST_ALPHA_OES, &v);
  EXPECT_EQ(v, GL_ONE);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA_OES, &v);
  EXPECT_EQ(v, GL_MAX_EXT);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::es1_test
