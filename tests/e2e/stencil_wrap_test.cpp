// GL 1.4 / GL_EXT_stencil_wrap: INCR_WRAP and DECR_WRAP wrap around instead of saturating.
#include <string>

#include "tests/e2e/support/gl_test.h"

#ifndef GL_INCR_WRAP
#define GL_INCR_WRAP 0x8507
#define GL_DECR_WRAP 0x8508
#endif

namespace pineda::test {
namespace {

class StencilWrapTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
  }
  GLubyte stencil_at(int x, int y) {
    GLubyte s = 0xEE;
    glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
    return s;
  }
};

TEST_F(StencilWrapTest, IncrWrapWrapsToZero) {
  glClearStencil(254);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 255);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 0);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 1);
  EXPECT_EQ(stencil_at(10, 10), 254);
  GLint op = 0;
  glGetIntegerv(GL_STENCIL_PASS_DEPTH_PASS, &op);
  EXPECT_EQ(op, GL_INCR_WRAP);
}

TEST_F(StencilWrapTest, DecrWrapWrapsToMaxOnFailToo) {
  glClearStencil(1);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilFunc(GL_NEVER, 0, 0xff);  // every fragment fails: the fail op runs
  glStencilOp(GL_DECR_WRAP, GL_KEEP, GL_KEEP);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 0);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 255);
  glStencilMask(0x0f);  // the write mask still applies: 255 - 1 = 254 keeps the high bits
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(stencil_at(1, 1), 254);
  GLint op = 0;
  glGetIntegerv(GL_STENCIL_FAIL, &op);
  EXPECT_EQ(op, GL_DECR_WRAP);
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_EXT_stencil_wrap"), std::string::npos);
}

}  // namespace
}  // namespace pineda::test
