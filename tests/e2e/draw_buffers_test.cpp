// GL 2.0 glDrawBuffers (ARB_draw_buffers, ATI_draw_buffers) on a single-buffered window-system
// framebuffer: its state, its errors, and fixed-function colour going to each selected buffer.
// Front and back together: tests/glx/glx_draw_buffers_test.cpp.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/state/get_helpers.h"

namespace pineda::test {
namespace {

class DrawBuffersTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    ASSERT_FALSE(get_bool(GL_DOUBLEBUFFER)) << "the test surface is single-buffered";
    pixel_projection();
    clear_to(0, 0, 0, 0);
  }
  std::vector<GLint> draw_buffers() {
    std::vector<GLint> v;
    for (int i = 0; i < 4; ++i) v.push_back(get_int(GL_DRAW_BUFFER0 + i));
    return v;
  }
  static std::vector<GLint> buffers(GLint b0, GLint b1 = GL_NONE, GLint b2 = GL_NONE, GLint b3 = GL_NONE) {
    return {b0, b1, b2, b3};
  }
};

TEST_F(DrawBuffersTest, Defaults) {
  EXPECT_EQ(get_int(GL_MAX_DRAW_BUFFERS), 8);
  EXPECT_EQ(draw_buffers(), buffers(GL_FRONT));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), GL_FRONT);
  get_int(GL_DRAW_BUFFER0 + 8);  // past MAX_DRAW_BUFFERS
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_ARB_draw_buffers "), std::string::npos);
  EXPECT_NE(ext.find("GL_ATI_draw_buffers "), std::string::npos);
}

TEST_F(DrawBuffersTest, SetsEachOutputAndNoneBeyondN) {
  const GLenum two[] = {GL_NONE, GL_FRONT_LEFT};
  glDrawBuffers(2, two);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(draw_buffers(), buffers(GL_NONE, GL_FRONT_LEFT));
  EXPECT_EQ(get_int(GL_DRAW_BUFFER), GL_NONE);
  const GLenum one[] = {GL_FRONT_LEFT};
  glDrawBuffersARB(1, one);
  EXPECT_EQ(draw_buffers(), buffers(GL_FRONT_LEFT));
  const GLenum four[] = {GL_NONE, GL_NONE, GL_NONE, GL_FRONT_LEFT};
  glDrawBuffersATI(4, four);
  EXPECT_EQ(draw_buffers(), buffers(GL_NONE, GL_NONE, GL_NONE, GL_FRONT_LEFT));
  glDrawBuffers(0, nullptr);
  EXPECT_EQ(draw_buffers(), buffers(GL_NONE));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(DrawBuffersTest, DrawBufferSetsTheOtherOutputsToNone) {
  const GLenum two[] = {GL_NONE, GL_FRONT_LEFT};
  glDrawBuffers(2, two);
  glDrawBuffer(GL_FRONT);
  EXPECT_EQ(draw_buffers(), buffers(GL_FRONT));
}

TEST_F(DrawBuffersTest, Errors) {
  const GLenum front_left[9] = {GL_FRONT_LEFT};  // the rest GL_NONE
  glDrawBuffers(-1, front_left);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDrawBuffers(9, front_left);  // more than MAX_DRAW_BUFFERS
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  struct Case {
    GLenum buffer;
    GLenum error;
  };
  const Case cases[] = {
      {GL_BACK_LEFT, GL_INVALID_OPERATION},   // no back buffer
      {GL_FRONT_RIGHT, GL_INVALID_OPERATION},  // not stereo
      {GL_AUX0, GL_INVALID_OPERATION},         // no aux buffers
      {GL_COLOR_ATTACHMENT0, GL_INVALID_OPERATION},  // not a framebuffer object
      {GL_FRONT, GL_INVALID_ENUM},  // names of several buffers
      {GL_BACK, GL_INVALID_ENUM},
      {GL_LEFT, GL_INVALID_ENUM},
      {GL_FRONT_AND_BACK, GL_INVALID_ENUM},
      {GL_TEXTURE_2D, GL_INVALID_ENUM},
  };
  for (const Case& c : cases) {
    const GLenum bufs[] = {GL_NONE, c.buffer};
    glDrawBuffers(2, bufs);
    EXPECT_EQ(glGetError(), c.error) << std::hex << c.buffer;
  }
  const GLenum twice[] = {GL_FRONT_LEFT, GL_NONE, GL_FRONT_LEFT};
  glDrawBuffers(3, twice);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  const GLenum nones[] = {GL_NONE, GL_NONE, GL_NONE};  // NONE may repeat
  glDrawBuffers(3, nones);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(draw_buffers(), buffers(GL_NONE));
  // Failed calls changed nothing.
  glDrawBuffers(1, front_left);
  glDrawBuffers(3, twice);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(draw_buffers(), buffers(GL_FRONT_LEFT));
  glBegin(GL_POINTS);
  glDrawBuffers(1, nones);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(draw_buffers(), buffers(GL_FRONT_LEFT));
}

TEST_F(DrawBuffersTest, FixedFunctionColourGoesToEverySelectedBuffer) {
  const GLenum second_only[] = {GL_NONE, GL_FRONT_LEFT};
  glDrawBuffers(2, second_only);
  glColor3f(0, 1, 0);
  glRecti(0, 0, 8, 8);
  EXPECT_TRUE(near_rgba(pixel(4, 4), {0, 255, 0, 255}));
  glDrawBuffers(0, nullptr);  // nothing selected: nothing is drawn or cleared
  glColor3f(1, 0, 0);
  glRecti(0, 0, 8, 8);
  clear_to(0, 0, 1, 1);
  EXPECT_TRUE(near_rgba(pixel(4, 4), {0, 255, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(20, 20), {0, 0, 0, 0}));
  expect_osmesa_buffer_matches_readback();
}

TEST_F(DrawBuffersTest, ColorBufferBitSavesEveryDrawBuffer) {
  const GLenum two[] = {GL_NONE, GL_FRONT_LEFT};
  glDrawBuffers(2, two);
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glDrawBuffer(GL_FRONT_LEFT);
  EXPECT_EQ(draw_buffers(), buffers(GL_FRONT_LEFT));
  glPopAttrib();
  EXPECT_EQ(draw_buffers(), buffers(GL_NONE, GL_FRONT_LEFT));
}

TEST_F(DrawBuffersTest, CompiledIntoDisplayLists) {
  const GLuint list = glGenLists(1);
  GLenum bufs[] = {GL_NONE, GL_FRONT_LEFT};
  glNewList(list, GL_COMPILE);
  glDrawBuffers(2, bufs);
  glEndList();
  bufs[1] = GL_NONE;  // the list keeps its own copy
  EXPECT_EQ(draw_buffers(), buffers(GL_FRONT));
  glCallList(list);
  EXPECT_EQ(draw_buffers(), buffers(GL_NONE, GL_FRONT_LEFT));
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
