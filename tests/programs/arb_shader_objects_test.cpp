// GL_ARB_shader_objects / GL_ARB_vertex_shader / GL_ARB_fragment_shader: the handle-based
// entry points, and a program drawn through the ARB names only.
#include <cstring>
#include <string>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

using ArbShaderObjectsTest = ProgramTest;

bool has_extension(const char* name) {
  const std::string all = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  return (" " + all).find(" " + std::string(name) + " ") != std::string::npos;
}

TEST_F(ArbShaderObjectsTest, Advertised) {
  EXPECT_TRUE(has_extension("GL_ARB_shader_objects"));
  EXPECT_TRUE(has_extension("GL_ARB_vertex_shader"));
  EXPECT_TRUE(has_extension("GL_ARB_fragment_shader"));
  EXPECT_TRUE(has_extension("GL_ARB_shading_language_100"));
}

TEST_F(ArbShaderObjectsTest, ObjectParametersAndHandles) {
  const GLhandleARB vs = glCreateShaderObjectARB(GL_VERTEX_SHADER_ARB);
  const GLhandleARB prog = glCreateProgramObjectARB();
  GLint v = 0;
  glGetObjectParameterivARB(vs, GL_OBJECT_TYPE_ARB, &v);
  EXPECT_EQ(v, GL_SHADER_OBJECT_ARB);
  glGetObjectParameterivARB(vs, GL_OBJECT_SUBTYPE_ARB, &v);
  EXPECT_EQ(v, GL_VERTEX_SHADER_ARB);
  glGetObjectParameterivARB(prog, GL_OBJECT_TYPE_ARB, &v);
  EXPECT_EQ(v, GL_PROGRAM_OBJECT_ARB);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glGetObjectParameterivARB(prog, GL_OBJECT_COMPILE_STATUS_ARB, &v);  // a shader's parameter
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetObjectParameterivARB(vs, GL_OBJECT_LINK_STATUS_ARB, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetObjectParameterivARB(vs, GL_TEXTURE_2D, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetObjectParameterivARB(4242, GL_OBJECT_TYPE_ARB, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const char* src = "void main() { gl_Position = gl_Vertex; }";
  glShaderSourceARB(vs, 1, &src, nullptr);
  glCompileShaderARB(vs);
  GLfloat f = 0;
  glGetObjectParameterfvARB(vs, GL_OBJECT_COMPILE_STATUS_ARB, &f);
  EXPECT_EQ(f, 1.f);
  glAttachObjectARB(prog, vs);
  glGetObjectParameterivARB(prog, GL_OBJECT_ATTACHED_OBJECTS_ARB, &v);
  EXPECT_EQ(v, 1);
  GLhandleARB attached = 0;
  GLsizei count = 0;
  glGetAttachedObjectsARB(prog, 1, &count, &attached);
  EXPECT_EQ(attached, vs);
  EXPECT_EQ(glGetHandleARB(GL_PROGRAM_OBJECT_ARB), 0u);
  glGetHandleARB(GL_VERTEX_SHADER_ARB);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDeleteObjectARB(vs);  // attached: flagged
  glGetObjectParameterivARB(vs, GL_OBJECT_DELETE_STATUS_ARB, &v);
  EXPECT_EQ(v, GL_TRUE);
  glDeleteObjectARB(prog);
  EXPECT_FALSE(glIsProgram(prog));
  EXPECT_FALSE(glIsShader(vs));
  glDeleteObjectARB(4242);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  char log[16];
  glGetInfoLogARB(4242, sizeof log, nullptr, log);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(ArbShaderObjectsTest, DrawsThroughTheArbNames) {
  const char* vs_src = "attribute vec4 pos; void main() { gl_Position = pos; }";
  const char* fs_src = "uniform vec4 c; void main() { gl_FragColor = c; }";
  const GLhandleARB vs = glCreateShaderObjectARB(GL_VERTEX_SHADER_ARB);
  const GLhandleARB fs = glCreateShaderObjectARB(GL_FRAGMENT_SHADER_ARB);
  glShaderSourceARB(vs, 1, &vs_src, nullptr);
  glShaderSourceARB(fs, 1, &fs_src, nullptr);
  glCompileShaderARB(vs);
  glCompileShaderARB(fs);
  const GLhandleARB prog = glCreateProgramObjectARB();
  glAttachObjectARB(prog, vs);
  glAttachObjectARB(prog, fs);
  glBindAttribLocationARB(prog, 0, "pos");
  glLinkProgramARB(prog);
  GLint linked = 0;
  glGetObjectParameterivARB(prog, GL_OBJECT_LINK_STATUS_ARB, &linked);
  ASSERT_EQ(linked, GL_TRUE);
  glUseProgramObjectARB(prog);
  EXPECT_EQ(glGetHandleARB(GL_PROGRAM_OBJECT_ARB), prog);
  const GLint c = glGetUniformLocationARB(prog, "c");
  const GLfloat color[4] = {0, 1, 0, 1};
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glUniform4fvARB(c, 1, color);
  glEndList();
  glCallList(list);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertexAttrib2fARB(0, -1, -1);
  glVertexAttrib2fARB(0, 3, -1);
  glVertexAttrib2fARB(0, -1, 3);
  glEnd();
  EXPECT_EQ(count_pixels({0, 255, 0, 255}), width() * height());
  GLfloat got[4] = {};
  glGetUniformfvARB(prog, c, got);
  EXPECT_EQ(got[1], 1.f);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ArbShaderObjectsTest, DerivativeHint) {
  GLint v = 0;
  glGetIntegerv(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, &v);
  EXPECT_EQ(v, GL_DONT_CARE);
  glHint(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, GL_NICEST);
  glGetIntegerv(GL_FRAGMENT_SHADER_DERIVATIVE_HINT, &v);
  EXPECT_EQ(v, GL_NICEST);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
