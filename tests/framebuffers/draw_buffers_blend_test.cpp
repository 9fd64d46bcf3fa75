// ARB_draw_buffers_blend: blend factors and equations per draw buffer, for fixed-function draws
// and fragment shaders; glBlendFunc and glBlendEquation set every buffer's; the indexed queries,
// the errors, the attribute stack and display lists.
#include <array>
#include <string>

#include "tests/framebuffers/four_draw_buffers.h"

namespace pineda::test {
namespace {

class DrawBuffersBlendTest : public FourDrawBuffersTest {
 protected:
  // Each buffer's own function: 0 replaces, 1 adds, 2 keeps its colour and takes the source
  // alpha, 3 subtracts its colour from the source's and keeps the larger alpha.
  static void set_functions() {
    glEnable(GL_BLEND);
    glBlendFunciARB(0, GL_ONE, GL_ZERO);
    glBlendFunciARB(1, GL_ONE, GL_ONE);
    glBlendFuncSeparateiARB(2, GL_ZERO, GL_ONE, GL_ONE, GL_ZERO);
    glBlendFunciARB(3, GL_ONE, GL_ONE);
    glBlendEquationSeparateiARB(3, GL_FUNC_SUBTRACT, GL_MAX);
  }
  // What set_functions() makes of kDrawn over kCleared in each buffer.
  static constexpr std::array<Rgba, 4> kBlended = {{
      {200, 100, 50, 150},
      {210, 120, 80, 190},
      {10, 20, 30, 150},
      {190, 80, 20, 150},
  }};

  GLint indexed(GLenum pname, GLuint i) {
    GLint v = -1;
    glGetIntegerIndexedvEXT(pname, i, &v);
    return v;
  }
  // Buffer i's factors and equations as the indexed queries return them.
  std::array<GLint, 6> function_of(GLuint i) {
    return {indexed(GL_BLEND_SRC_RGB, i),   indexed(GL_BLEND_DST_RGB, i),      indexed(GL_BLEND_SRC_ALPHA, i),
            indexed(GL_BLEND_DST_ALPHA, i), indexed(GL_BLEND_EQUATION_RGB, i), indexed(GL_BLEND_EQUATION_ALPHA, i)};
  }
};

TEST_F(DrawBuffersBlendTest, Advertised) {
  const std::string ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(ext.find("GL_ARB_draw_buffers_blend "), std::string::npos);
}

TEST_F(DrawBuffersBlendTest, FixedFunctionBlendsEachBufferWithItsFunction) {
  set_functions();
  draw_quad(kDrawn);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(attachment_pixel(i, 3, 3), kBlended[size_t(i)]) << "draw buffer " << i;
    EXPECT_EQ(attachment_pixel(i, 12, 12), kCleared) << "draw buffer " << i;
  }
}

TEST_F(DrawBuffersBlendTest, ShaderBlendsEachBufferWithItsFunction) {
  const GLuint p = fragment_program(
      "void main() {\n"
      "  for (int i = 0; i < 4; ++i) gl_FragData[i] = gl_Color;\n"
      "}\n");
  glUseProgram(p);
  set_functions();
  draw_quad(kDrawn);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(attachment_pixel(i, 3, 3), kBlended[size_t(i)]) << "draw buffer " << i;
  glDeleteProgram(p);
}

TEST_F(DrawBuffersBlendTest, QueriesReturnEachBuffersFunction) {
  set_functions();
  EXPECT_EQ(function_of(0), (std::array<GLint, 6>{GL_ONE, GL_ZERO, GL_ONE, GL_ZERO, GL_FUNC_ADD, GL_FUNC_ADD}));
  EXPECT_EQ(function_of(1), (std::array<GLint, 6>{GL_ONE, GL_ONE, GL_ONE, GL_ONE, GL_FUNC_ADD, GL_FUNC_ADD}));
  EXPECT_EQ(function_of(2), (std::array<GLint, 6>{GL_ZERO, GL_ONE, GL_ONE, GL_ZERO, GL_FUNC_ADD, GL_FUNC_ADD}));
  EXPECT_EQ(function_of(3), (std::array<GLint, 6>{GL_ONE, GL_ONE, GL_ONE, GL_ONE, GL_FUNC_SUBTRACT, GL_MAX}));
  EXPECT_EQ(function_of(7), (std::array<GLint, 6>{GL_ONE, GL_ZERO, GL_ONE, GL_ZERO, GL_FUNC_ADD, GL_FUNC_ADD}));
  // The unindexed queries answer draw buffer 0's.
  glBlendFuncSeparateiARB(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA);
  glBlendEquationSeparateiARB(0, GL_MIN, GL_FUNC_REVERSE_SUBTRACT);
  const std::pair<GLenum, GLint> unindexed[] = {
      {GL_BLEND_SRC_RGB, GL_SRC_ALPHA},  {GL_BLEND_DST_RGB, GL_ONE_MINUS_SRC_ALPHA},
      {GL_BLEND_SRC_ALPHA, GL_DST_ALPHA}, {GL_BLEND_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA},
      {GL_BLEND_EQUATION_RGB, GL_MIN},   {GL_BLEND_EQUATION_ALPHA, GL_FUNC_REVERSE_SUBTRACT}};
  for (const auto& [pname, value] : unindexed) {
    GLint v = -1;
    glGetIntegerv(pname, &v);
    EXPECT_EQ(v, value) << std::hex << pname;
  }
  // GL 1.0's names for the RGB factors.
  EXPECT_EQ(indexed(GL_BLEND_SRC, 3), GL_ONE);
  EXPECT_EQ(indexed(GL_BLEND_DST, 2), GL_ONE);
  EXPECT_EQ(indexed(GL_BLEND_SRC, 2), GL_ZERO);
  GLboolean b = 9;
  glGetBooleanIndexedvEXT(GL_BLEND_DST_RGB, 2, &b);
  EXPECT_EQ(b, GL_TRUE);  // GL_ONE
  glGetBooleanIndexedvEXT(GL_BLEND_SRC_RGB, 2, &b);
  EXPECT_EQ(b, GL_FALSE);  // GL_ZERO
}

TEST_F(DrawBuffersBlendTest, UnindexedCallsSetEveryBuffer) {
  set_functions();
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (GLuint i = 0; i < 8; ++i) {
    const std::array<GLint, 6> f = function_of(i);
    EXPECT_EQ(f[0], GL_SRC_ALPHA) << i;
    EXPECT_EQ(f[3], GL_ONE_MINUS_SRC_ALPHA) << i;
    EXPECT_EQ(f[4], i == 3 ? GL_FUNC_SUBTRACT : GL_FUNC_ADD) << i;  // the equations stay
  }
  glBlendEquation(GL_MAX);
  for (GLuint i = 0; i < 8; ++i) {
    EXPECT_EQ(indexed(GL_BLEND_EQUATION_RGB, i), GL_MAX) << i;
    EXPECT_EQ(indexed(GL_BLEND_EQUATION_ALPHA, i), GL_MAX) << i;
  }
}

TEST_F(DrawBuffersBlendTest, ErrorsChangeNothing) {
  set_functions();
  glBlendFunciARB(8, GL_ONE, GL_ONE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBlendFuncSeparateiARB(0xFFFFFFFFu, GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBlendEquationiARB(8, GL_MIN);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBlendEquationSeparateiARB(8, GL_MIN, GL_MIN);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glBlendFunciARB(1, GL_ONE, GL_FUNC_ADD);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBlendFuncSeparateiARB(2, GL_ONE, GL_ONE, GL_ONE, GL_MIN);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBlendEquationiARB(1, GL_ONE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glBlendEquationSeparateiARB(3, GL_FUNC_ADD, GL_ZERO);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLint v = 77;
  glGetIntegerIndexedvEXT(GL_BLEND_SRC_RGB, 8, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  EXPECT_EQ(v, 77);
  EXPECT_EQ(function_of(1), (std::array<GLint, 6>{GL_ONE, GL_ONE, GL_ONE, GL_ONE, GL_FUNC_ADD, GL_FUNC_ADD}));
  EXPECT_EQ(function_of(2), (std::array<GLint, 6>{GL_ZERO, GL_ONE, GL_ONE, GL_ZERO, GL_FUNC_ADD, GL_FUNC_ADD}));
  EXPECT_EQ(function_of(3), (std::array<GLint, 6>{GL_ONE, GL_ONE, GL_ONE, GL_ONE, GL_FUNC_SUBTRACT, GL_MAX}));
}

TEST_F(DrawBuffersBlendTest, AttribStackKeepsEveryBuffersFunction) {
  set_functions();
  glPushAttrib(GL_COLOR_BUFFER_BIT);
  glBlendFunciARB(2, GL_DST_COLOR, GL_SRC_COLOR);
  glBlendEquationiARB(1, GL_MIN);
  glPopAttrib();
  EXPECT_EQ(function_of(1), (std::array<GLint, 6>{GL_ONE, GL_ONE, GL_ONE, GL_ONE, GL_FUNC_ADD, GL_FUNC_ADD}));
  EXPECT_EQ(function_of(2), (std::array<GLint, 6>{GL_ZERO, GL_ONE, GL_ONE, GL_ZERO, GL_FUNC_ADD, GL_FUNC_ADD}));
  draw_quad(kDrawn);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(attachment_pixel(i, 3, 3), kBlended[size_t(i)]) << "draw buffer " << i;
}

TEST_F(DrawBuffersBlendTest, DisplayListsRecordTheIndexedCalls) {
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBlendFunciARB(1, GL_ONE, GL_ONE);
  glBlendEquationSeparateiARB(3, GL_FUNC_SUBTRACT, GL_MAX);
  glEndList();
  EXPECT_EQ(indexed(GL_BLEND_DST_RGB, 1), GL_ZERO);  // compiled, not executed
  EXPECT_EQ(indexed(GL_BLEND_EQUATION_ALPHA, 3), GL_FUNC_ADD);
  glCallList(list);
  EXPECT_EQ(indexed(GL_BLEND_DST_RGB, 1), GL_ONE);
  EXPECT_EQ(indexed(GL_BLEND_EQUATION_RGB, 3), GL_FUNC_SUBTRACT);
  EXPECT_EQ(indexed(GL_BLEND_EQUATION_ALPHA, 3), GL_MAX);
  glDeleteLists(list, 1);
}

}  // namespace
}  // namespace pineda::test
