// GL_OES_vertex_array_object in an OpenGL ES 2.0 context: advertised, the four functions through
// eglGetProcAddress, VERTEX_ARRAY_BINDING_OES, and each object drawing its generic arrays.
#include <gtest/gtest.h>

#include <cstring>

#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

TEST(Es2VertexArrayObject, OesFunctionsAndDrawing) {
  Es2Context context(8, 8);
  ASSERT_TRUE(context.ok()) << context.error();
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  ASSERT_NE(extensions, nullptr);
  EXPECT_NE(std::strstr(extensions, "GL_OES_vertex_array_object "), nullptr);
  auto gen = reinterpret_cast<PFNGLGENVERTEXARRAYSOESPROC>(eglGetProcAddress("glGenVertexArraysOES"));
  auto bind = reinterpret_cast<PFNGLBINDVERTEXARRAYOESPROC>(eglGetProcAddress("glBindVertexArrayOES"));
  auto is = reinterpret_cast<PFNGLISVERTEXARRAYOESPROC>(eglGetProcAddress("glIsVertexArrayOES"));
  auto del = reinterpret_cast<PFNGLDELETEVERTEXARRAYSOESPROC>(eglGetProcAddress("glDeleteVertexArraysOES"));
  ASSERT_TRUE(gen && bind && is && del);

  GLuint vaos[2] = {};
  gen(2, vaos);
  EXPECT_EQ(is(vaos[0]), GL_FALSE);
  bind(vaos[1] + 50);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));

  const GLuint program = build_program(
      "attribute vec2 pos; attribute vec4 col; varying vec4 c;"
      "void main() { gl_Position = vec4(pos, 0.0, 1.0); c = col; }",
      "precision mediump float; varying vec4 c; void main() { gl_FragColor = c; }", {{"pos", 0}, {"col", 1}});
  ASSERT_NE(program, 0u);
  glUseProgram(program);
  static const float quad[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
  static const GLubyte red[16] = {255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255};
  static const GLubyte blue[16] = {0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255, 0, 0, 255, 255};
  for (int i = 0; i < 2; ++i) {
    bind(vaos[i]);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, quad);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, i == 0 ? red : blue);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
  }
  EXPECT_EQ(is(vaos[0]), GL_TRUE);
  GLint binding = -1;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING_OES, &binding);
  EXPECT_EQ(binding, GLint(vaos[1]));
  bind(vaos[0]);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  EXPECT_EQ(read_pixel(3, 3), 0xff0000ffu);
  bind(vaos[1]);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  EXPECT_EQ(read_pixel(3, 3), 0x0000ffffu);
  // Object 0 has no array enabled.
  bind(0);
  GLint enabled = -1;
  glGetVertexAttribiv(0, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &enabled);
  EXPECT_EQ(enabled, GL_FALSE);
  del(2, vaos);
  EXPECT_EQ(is(vaos[1]), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glDeleteProgram(program);
}

}  // namespace
}  // namespace pineda::es2_test
