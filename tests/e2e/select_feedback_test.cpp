// glRenderMode GL_SELECT and GL_FEEDBACK: hit records and feedback tokens with exact values.
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class SelectFeedbackTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();  // glOrtho(0, 32, 0, 32, -1, 1): window z = (1 - z) / 2
    clear_to(0, 0, 0, 0);
  }
  static void quad(float x0, float y0, float x1, float y1, float z) {
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
  }
};

constexpr GLuint kZHalf = 2147483648u;  // 0.5 * (2^32 - 1), rounded

TEST_F(SelectFeedbackTest, SelectionRecordsHitsWithNamesAndDepths) {
  GLuint buffer[64];
  std::fill(std::begin(buffer), std::end(buffer), 0xdeadbeefu);
  glSelectBuffer(64, buffer);
  EXPECT_EQ(glRenderMode(GL_SELECT), 0);
  GLint mode = 0;
  glGetIntegerv(GL_RENDER_MODE, &mode);
  EXPECT_EQ(mode, GL_SELECT);
  glInitNames();
  glPushName(7);
  quad(2, 2, 6, 6, 0.f);     // z 0.5
  quad(40, 40, 50, 50, 0.f);  // outside the view volume: no hit
  glLoadName(8);              // ends the record of name 7
  quad(40, 40, 50, 50, 0.f);  // no hit: no record for 8
  glPushName(9);
  quad(2, 2, 6, 6, 1.f);      // z 0
  quad(2, 2, 6, 6, -1.f);     // z 1
  GLint depth = 0;
  glGetIntegerv(GL_NAME_STACK_DEPTH, &depth);
  EXPECT_EQ(depth, 2);
  EXPECT_EQ(glRenderMode(GL_RENDER), 2);
  const GLuint expected[] = {1, kZHalf, kZHalf, 7, 2, 0, 0xffffffffu, 8, 9};
  for (size_t i = 0; i < std::size(expected); ++i) EXPECT_EQ(buffer[i], expected[i]) << "word " << i;
  EXPECT_EQ(buffer[std::size(expected)], 0xdeadbeefu);
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());  // nothing was rendered
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(SelectFeedbackTest, ClippedPrimitivesUseTheirVisibleDepths) {
  GLuint buffer[8] = {};
  glSelectBuffer(8, buffer);
  glRenderMode(GL_SELECT);
  glPushName(1);
  // A line from z = 3 (behind the far plane, clipped at window z 0... ) to z = -0.5.
  glBegin(GL_LINES);
  glVertex3f(4, 4, 3.f);   // outside: clipped to z = 1 (window 0)
  glVertex3f(8, 8, -0.5f);  // window 0.75
  glEnd();
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(buffer[1], 0u);
  EXPECT_EQ(buffer[2], 3221225471u);  // 0.75 * (2^32 - 1), rounded
}

TEST_F(SelectFeedbackTest, SelectBufferOverflowReturnsMinusOne) {
  GLuint buffer[5] = {};
  glSelectBuffer(4, buffer);
  buffer[4] = 99;
  glRenderMode(GL_SELECT);
  glPushName(1);
  glPushName(2);
  quad(2, 2, 6, 6, 0.f);
  EXPECT_EQ(glRenderMode(GL_RENDER), -1);  // the record needs 5 words
  EXPECT_EQ(buffer[3], 1u);
  EXPECT_EQ(buffer[4], 99u);
}

TEST_F(SelectFeedbackTest, NameStackErrors) {
  GLuint buffer[4];
  glSelectBuffer(4, buffer);
  glRenderMode(GL_SELECT);
  glLoadName(1);  // empty stack
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glPopName();
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW));
  for (int i = 0; i < 64; ++i) glPushName(GLuint(i));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glPushName(64);
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_OVERFLOW));
  glSelectBuffer(4, buffer);  // not while selecting
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glRenderMode(GL_RENDER);
  glPushName(1);  // ignored outside selection
  GLint depth = -1;
  glGetIntegerv(GL_NAME_STACK_DEPTH, &depth);
  EXPECT_EQ(depth, 0);
  EXPECT_EQ(glRenderMode(GL_POINTS), 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glSelectBuffer(-1, buffer);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  GLfloat fb[4];
  glFeedbackBuffer(4, GL_RGBA, fb);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBegin(GL_POINTS);
  glRenderMode(GL_SELECT);
  glEnd();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(SelectFeedbackTest, RenderModeWithoutABufferIsAnError) {
  EXPECT_EQ(glRenderMode(GL_FEEDBACK), 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  GLint mode = 0;
  glGetIntegerv(GL_RENDER_MODE, &mode);
  EXPECT_EQ(mode, GL_RENDER);
}

TEST_F(SelectFeedbackTest, FeedbackTokens3DColor) {
  GLfloat buffer[64];
  std::fill(std::begin(buffer), std::end(buffer), -7.f);
  glFeedbackBuffer(64, GL_3D_COLOR, buffer);
  glRenderMode(GL_FEEDBACK);
  glColor4f(1, 0.5f, 0.25f, 1);
  glBegin(GL_POINTS);
  glVertex3f(3, 4, 0.f);
  glEnd();
  glPassThrough(42.f);
  glBegin(GL_LINE_STRIP);
  glVertex2f(1, 1);
  glVertex2f(5, 1);
  glVertex2f(5, 9);
  glEnd();
  const GLint n = glRenderMode(GL_RENDER);
  const std::vector<GLfloat> expected = {
      GL_POINT_TOKEN, 3, 4, 0.5f, 1, 0.5f, 0.25f, 1,
      GL_PASS_THROUGH_TOKEN, 42,
      GL_LINE_RESET_TOKEN, 1, 1, 0.5f, 1, 0.5f, 0.25f, 1, 5, 1, 0.5f, 1, 0.5f, 0.25f, 1,
      GL_LINE_TOKEN, 5, 1, 0.5f, 1, 0.5f, 0.25f, 1, 5, 9, 0.5f, 1, 0.5f, 0.25f, 1};
  ASSERT_EQ(n, GLint(expected.size()));
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_FLOAT_EQ(buffer[i], expected[i]) << "value " << i;
  EXPECT_EQ(buffer[expected.size()], -7.f);
}

TEST_F(SelectFeedbackTest, FeedbackPolygonsAreClippedAndCulled) {
  GLfloat buffer[32];
  glFeedbackBuffer(32, GL_2D, buffer);
  glRenderMode(GL_FEEDBACK);
  glBegin(GL_TRIANGLES);  // counter-clockwise, its right part beyond x = 32
  glVertex2f(20, 0);
  glVertex2f(40, 0);
  glVertex2f(20, 10);
  glEnd();
  glEnable(GL_CULL_FACE);  // back faces culled: a clockwise triangle gives nothing
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(0, 10);
  glVertex2f(10, 0);
  glEnd();
  const std::vector<GLfloat> expected = {GL_POLYGON_TOKEN, 4, 20, 0, 32, 0, 32, 4, 20, 10};
  ASSERT_EQ(glRenderMode(GL_RENDER), GLint(expected.size()));
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_FLOAT_EQ(buffer[i], expected[i]) << "value " << i;
}

TEST_F(SelectFeedbackTest, Feedback4DColorTextureAndOverflow) {
  GLfloat buffer[12];
  glFeedbackBuffer(12, GL_4D_COLOR_TEXTURE, buffer);
  GLint type = 0;
  glGetIntegerv(GL_FEEDBACK_BUFFER_TYPE, &type);
  EXPECT_EQ(type, GL_4D_COLOR_TEXTURE);
  glRenderMode(GL_FEEDBACK);
  glColor3f(0, 1, 0);
  glTexCoord4f(0.5f, 0.25f, 2, 1);
  glBegin(GL_POINTS);
  glVertex4f(4, 6, 0, 2);  // w = 2: window (2, 3)
  glEnd();
  EXPECT_EQ(glRenderMode(GL_RENDER), -1);  // the point needs 13 values
  const GLfloat expected[] = {GL_POINT_TOKEN, 2, 3, 0.5f, 2, 0, 1, 0, 1, 0.5f, 0.25f, 2};
  for (size_t i = 0; i < std::size(expected); ++i) EXPECT_FLOAT_EQ(buffer[i], expected[i]) << "value " << i;
  void* p = nullptr;
  glGetPointerv(GL_FEEDBACK_BUFFER_POINTER, &p);
  EXPECT_EQ(p, buffer);
}

TEST_F(SelectFeedbackTest, NameCommandsAreCompiledIntoLists) {
  GLuint buffer[16] = {};
  glSelectBuffer(16, buffer);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glInitNames();
  glPushName(5);
  glRecti(1, 1, 3, 3);
  glEndList();
  glRenderMode(GL_SELECT);
  glCallList(list);
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(buffer[0], 1u);
  EXPECT_EQ(buffer[3], 5u);
}

}  // namespace
}  // namespace pineda::test
