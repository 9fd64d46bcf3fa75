// GL 2.0 separate stencil (and ATI_separate_stencil): each face has its own function,
// reference, masks and operations; back-facing polygons use the back face's.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class SeparateStencilTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
  }
  GLubyte stencil_at(int x, int y) {
    GLubyte s = 0xEE;
    glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
    return s;
  }
  GLint get(GLenum pname) {
    GLint v = -12345;
    glGetIntegerv(pname, &v);
    return v;
  }
  // Counter-clockwise: front-facing, over [0, 16) x [0, 16).
  void front_square() { glRecti(0, 0, 16, 16); }
  // Clockwise: back-facing, over [16, 32) x [0, 16).
  void back_square() { glRecti(32, 0, 16, 16); }

  struct Face {
    GLint func, ref, value_mask, write_mask, fail, zfail, zpass;
  };
  Face front() {
    return {get(GL_STENCIL_FUNC), get(GL_STENCIL_REF), get(GL_STENCIL_VALUE_MASK), get(GL_STENCIL_WRITEMASK),
            get(GL_STENCIL_FAIL), get(GL_STENCIL_PASS_DEPTH_FAIL), get(GL_STENCIL_PASS_DEPTH_PASS)};
  }
  Face back() {
    return {get(GL_STENCIL_BACK_FUNC), get(GL_STENCIL_BACK_REF), get(GL_STENCIL_BACK_VALUE_MASK),
            get(GL_STENCIL_BACK_WRITEMASK), get(GL_STENCIL_BACK_FAIL), get(GL_STENCIL_BACK_PASS_DEPTH_FAIL),
            get(GL_STENCIL_BACK_PASS_DEPTH_PASS)};
  }
  static void expect_face(const Face& f, const Face& want) {
    EXPECT_EQ(f.func, want.func);
    EXPECT_EQ(f.ref, want.ref);
    EXPECT_EQ(f.value_mask, want.value_mask);
    EXPECT_EQ(f.write_mask, want.write_mask);
    EXPECT_EQ(f.fail, want.fail);
    EXPECT_EQ(f.zfail, want.zfail);
    EXPECT_EQ(f.zpass, want.zpass);
  }
  static constexpr Face kDefault = {GL_ALWAYS, 0, -1, -1, GL_KEEP, GL_KEEP, GL_KEEP};
};

TEST_F(SeparateStencilTest, BackStateDefaults) {
  expect_face(back(), kDefault);
  expect_face(front(), kDefault);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SeparateStencilTest, EachFaceIsSetAlone) {
  glStencilFuncSeparate(GL_BACK, GL_LESS, 5, 0x0f);
  glStencilOpSeparate(GL_BACK, GL_ZERO, GL_INCR, GL_DECR_WRAP);
  glStencilMaskSeparate(GL_BACK, 0x3c);
  expect_face(back(), {GL_LESS, 5, 0x0f, 0x3c, GL_ZERO, GL_INCR, GL_DECR_WRAP});
  expect_face(front(), kDefault);

  glStencilFuncSeparate(GL_FRONT, GL_GEQUAL, 9, 0xf0);
  glStencilOpSeparate(GL_FRONT, GL_INVERT, GL_REPLACE, GL_INCR_WRAP);
  glStencilMaskSeparate(GL_FRONT, 0x81);
  expect_face(front(), {GL_GEQUAL, 9, 0xf0, 0x81, GL_INVERT, GL_REPLACE, GL_INCR_WRAP});
  expect_face(back(), {GL_LESS, 5, 0x0f, 0x3c, GL_ZERO, GL_INCR, GL_DECR_WRAP});

  glStencilFuncSeparate(GL_FRONT_AND_BACK, GL_NOTEQUAL, 2, 0x11);
  glStencilOpSeparate(GL_FRONT_AND_BACK, GL_DECR, GL_KEEP, GL_ZERO);
  glStencilMaskSeparate(GL_FRONT_AND_BACK, 0x22);
  expect_face(front(), {GL_NOTEQUAL, 2, 0x11, 0x22, GL_DECR, GL_KEEP, GL_ZERO});
  expect_face(back(), {GL_NOTEQUAL, 2, 0x11, 0x22, GL_DECR, GL_KEEP, GL_ZERO});
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SeparateStencilTest, OneFaceCallsSetBothFaces) {
  glStencilFuncSeparate(GL_BACK, GL_LESS, 5, 0x0f);
  glStencilFunc(GL_EQUAL, 3, 0x7);
  glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
  glStencilMask(0x55);
  expect_face(back(), {GL_EQUAL, 3, 0x7, 0x55, GL_INCR, GL_DECR, GL_INVERT});
  expect_face(front(), {GL_EQUAL, 3, 0x7, 0x55, GL_INCR, GL_DECR, GL_INVERT});
}

TEST_F(SeparateStencilTest, ReferenceIsClampedToTheBufferRange) {
  glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 300, 0xff);
  EXPECT_EQ(get(GL_STENCIL_BACK_REF), 255);
  glStencilFuncSeparate(GL_BACK, GL_ALWAYS, -4, 0xff);
  EXPECT_EQ(get(GL_STENCIL_BACK_REF), 0);
  EXPECT_EQ(get(GL_STENCIL_REF), 0);
}

TEST_F(SeparateStencilTest, BadArgumentsAreRejectedAndChangeNothing) {
  glStencilFuncSeparate(GL_LEFT, GL_LESS, 1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glStencilFuncSeparate(GL_BACK, GL_KEEP, 1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glStencilOpSeparate(GL_FRONT_LEFT, GL_KEEP, GL_KEEP, GL_KEEP);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glStencilOpSeparate(GL_BACK, GL_KEEP, GL_LESS, GL_KEEP);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glStencilMaskSeparate(GL_NONE, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glStencilFuncSeparateATI(GL_LESS, GL_INCR, 1, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  expect_face(front(), kDefault);
  expect_face(back(), kDefault);
  glBegin(GL_TRIANGLES);
  glStencilMaskSeparate(GL_BACK, 0);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(get(GL_STENCIL_BACK_WRITEMASK), -1);
}

TEST_F(SeparateStencilTest, BackFacingPolygonsUseTheBackOperations) {
  glEnable(GL_STENCIL_TEST);
  glStencilFuncSeparate(GL_FRONT, GL_ALWAYS, 3, 0xff);
  glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 9, 0xff);
  glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_REPLACE);
  glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_INVERT);
  glStencilMaskSeparate(GL_BACK, 0x0f);
  front_square();
  back_square();
  EXPECT_EQ(stencil_at(8, 8), 3);
  EXPECT_EQ(stencil_at(24, 8), 0x0f);  // ~0 under the back write mask
  EXPECT_EQ(stencil_at(8, 24), 0);
  // Both squares once more: REPLACE keeps 3; INVERT of the low bits gives 0 again.
  front_square();
  back_square();
  EXPECT_EQ(stencil_at(8, 8), 3);
  EXPECT_EQ(stencil_at(24, 8), 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SeparateStencilTest, BackFacingPolygonsUseTheBackFunctionAndReference) {
  glClearStencil(4);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFuncSeparate(GL_FRONT, GL_EQUAL, 4, 0xff);    // passes on 4
  glStencilFuncSeparate(GL_BACK, GL_EQUAL, 5, 0xff);     // fails on 4
  glStencilOpSeparate(GL_BACK, GL_INCR, GL_KEEP, GL_KEEP);  // so the back face's fail op runs
  glColor3f(0, 1, 0);
  front_square();
  back_square();
  EXPECT_TRUE(near_rgba(pixel(8, 8), {0, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(24, 8), {0, 0, 0, 0}));
  EXPECT_EQ(stencil_at(24, 8), 5);
  EXPECT_EQ(stencil_at(8, 8), 4);
  // Now the back square's stencil is 5: its function passes there.
  glColor3f(1, 0, 0);
  back_square();
  EXPECT_TRUE(near_rgba(pixel(24, 8), {255, 0, 0, 255}));
  // The back value mask applies to the back face only.
  glStencilFuncSeparate(GL_BACK, GL_EQUAL, 0x14, 0x0f);  // 0x14 & 0x0f == 4 == stencil 4 & 0x0f
  glColor3f(0, 0, 1);
  glRecti(32, 16, 16, 32);  // back-facing, over stencil 4
  EXPECT_TRUE(near_rgba(pixel(24, 24), {0, 0, 255, 255}));
}

TEST_F(SeparateStencilTest, FacingFollowsFrontFaceAndPolygonModeLines) {
  glEnable(GL_STENCIL_TEST);
  glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR);
  glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_INVERT);
  glFrontFace(GL_CW);  // the clockwise square is now the front face
  back_square();
  EXPECT_EQ(stencil_at(24, 8), 1);
  front_square();
  EXPECT_EQ(stencil_at(8, 8), 255);
  glFrontFace(GL_CCW);
  // A back-facing polygon drawn as lines: its edges use the back state too.
  glClear(GL_STENCIL_BUFFER_BIT);
  glPolygonMode(GL_BACK, GL_LINE);
  glBegin(GL_QUADS);
  glVertex2f(20.5f, 4.5f);
  glVertex2f(20.5f, 12.5f);
  glVertex2f(28.5f, 12.5f);
  glVertex2f(28.5f, 4.5f);
  glEnd();
  EXPECT_EQ(stencil_at(20, 8), 255);
  EXPECT_EQ(stencil_at(24, 8), 0);
  // Points and lines are front-facing.
  glBegin(GL_LINES);
  glVertex2f(2.f, 20.5f);
  glVertex2f(10.f, 20.5f);
  glEnd();
  EXPECT_EQ(stencil_at(5, 20), 1);
}

TEST_F(SeparateStencilTest, ClearUsesTheFrontWriteMask) {
  glStencilMaskSeparate(GL_FRONT, 0x0f);
  glStencilMaskSeparate(GL_BACK, 0x00);
  glClearStencil(0xff);
  glClear(GL_STENCIL_BUFFER_BIT);
  EXPECT_EQ(stencil_at(3, 3), 0x0f);
}

TEST_F(SeparateStencilTest, AtiSeparateStencil) {
  glStencilFuncSeparateATI(GL_LESS, GL_GREATER, 6, 0x3f);
  glStencilOpSeparateATI(GL_BACK, GL_ZERO, GL_REPLACE, GL_INCR);
  expect_face(front(), {GL_LESS, 6, 0x3f, -1, GL_KEEP, GL_KEEP, GL_KEEP});
  expect_face(back(), {GL_GREATER, 6, 0x3f, -1, GL_ZERO, GL_REPLACE, GL_INCR});
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_ATI_separate_stencil "), std::string::npos);
}

TEST_F(SeparateStencilTest, PushAttribSavesTheBackFace) {
  glStencilFuncSeparate(GL_BACK, GL_LESS, 5, 0x0f);
  glStencilOpSeparate(GL_BACK, GL_ZERO, GL_INCR, GL_DECR_WRAP);
  glStencilMaskSeparate(GL_BACK, 0x3c);
  glPushAttrib(GL_STENCIL_BUFFER_BIT);
  glStencilFuncSeparate(GL_BACK, GL_NEVER, 1, 1);
  glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilMaskSeparate(GL_BACK, 0);
  glPopAttrib();
  expect_face(back(), {GL_LESS, 5, 0x0f, 0x3c, GL_ZERO, GL_INCR, GL_DECR_WRAP});
  // The back face's rendering state is restored with it.
  glEnable(GL_STENCIL_TEST);
  glStencilFuncSeparate(GL_BACK, GL_ALWAYS, 0, 0xff);
  back_square();
  EXPECT_EQ(stencil_at(24, 8), 0xff & 0x3c);  // DECR_WRAP of 0, under mask 0x3c
  // Another group leaves it alone.
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glStencilMaskSeparate(GL_BACK, 0x01);
  glPopAttrib();
  EXPECT_EQ(get(GL_STENCIL_BACK_WRITEMASK), 0x01);
}

TEST_F(SeparateStencilTest, CompiledIntoDisplayLists) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glStencilFuncSeparate(GL_BACK, GL_GREATER, 7, 0x70);
  glStencilOpSeparate(GL_BACK, GL_INVERT, GL_ZERO, GL_REPLACE);
  glStencilMaskSeparate(GL_BACK, 0x07);
  glEndList();
  expect_face(back(), kDefault);
  glCallList(list);
  expect_face(back(), {GL_GREATER, 7, 0x70, 0x07, GL_INVERT, GL_ZERO, GL_REPLACE});
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
