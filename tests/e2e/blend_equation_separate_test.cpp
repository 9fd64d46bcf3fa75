// GL 2.0 glBlendEquationSeparate (the core name of EXT_blend_equation_separate): the colour
// and alpha equations apart, their queries, the attribute stack and display lists.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class BlendEquationSeparateTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
  }
  void clear_dst() { clear_to(100 / 255.f, 150 / 255.f, 50 / 255.f, 60 / 255.f); }
  void draw_src() {
    glColor4ub(20, 200, 40, 80);
    glRecti(0, 0, 2, 2);
  }
};

TEST_F(BlendEquationSeparateTest, DefaultsAreFuncAdd) {
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_FUNC_ADD);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_FUNC_ADD);
}

TEST_F(BlendEquationSeparateTest, MinForColourMaxForAlpha) {
  clear_dst();
  glBlendEquationSeparate(GL_MIN, GL_MAX);
  draw_src();
  EXPECT_TRUE(near_rgba(pixel(1, 1), {20, 150, 40, 80}));
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_MIN);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION), GL_MIN);  // the same state as BLEND_EQUATION_RGB
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_MAX);
}

TEST_F(BlendEquationSeparateTest, SubtractForColourAddForAlpha) {
  clear_dst();
  glBlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_FUNC_ADD);
  draw_src();
  // dst - src, clamped at 0; alpha added.
  EXPECT_TRUE(near_rgba(pixel(1, 1), {80, 0, 10, 140}));
  glBlendEquation(GL_FUNC_SUBTRACT);  // sets both
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_FUNC_SUBTRACT);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_FUNC_SUBTRACT);
}

TEST_F(BlendEquationSeparateTest, BadModesChangeNothing) {
  glBlendEquationSeparate(GL_MIN, GL_MAX);
  glBlendEquationSeparate(GL_FUNC_ADD, GL_ONE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBlendEquationSeparate(GL_ZERO, GL_FUNC_ADD);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_MIN);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_MAX);
}

TEST_F(BlendEquationSeparateTest, SavedWithColorBufferBitAndCompiledIntoLists) {
  glBlendEquationSeparate(GL_MIN, GL_MAX);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glBlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_SUBTRACT);
  glPopAttrib();
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_MIN);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_MAX);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MIN);
  glEndList();
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_MIN);
  glCallList(list);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_RGB), GL_FUNC_SUBTRACT);
  EXPECT_EQ(get_int(GL_BLEND_EQUATION_ALPHA), GL_MIN);
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
