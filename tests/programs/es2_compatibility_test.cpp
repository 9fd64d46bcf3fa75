// GL_ARB_ES2_compatibility on desktop GL: the ES 2.0 entry points and queries, GL_FIXED
// generic arrays, and framebuffer completeness without the draw and read buffer rules.
#include <cstring>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

using Es2CompatibilityTest = ProgramTest;

TEST_F(Es2CompatibilityTest, Advertised) {
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  ASSERT_NE(extensions, nullptr);
  EXPECT_NE(std::strstr(extensions, "GL_ARB_ES2_compatibility "), nullptr);
}

TEST_F(Es2CompatibilityTest, QueriesAndShaderCompilerCalls) {
  GLint v = -1;
  glGetIntegerv(GL_MAX_VERTEX_UNIFORM_VECTORS, &v);
  GLint components = -1;
  glGetIntegerv(GL_MAX_VERTEX_UNIFORM_COMPONENTS, &components);
  EXPECT_EQ(v, components / 4);
  glGetIntegerv(GL_MAX_VARYING_VECTORS, &v);
  GLint varying_floats = -1;
  glGetIntegerv(GL_MAX_VARYING_FLOATS, &varying_floats);
  EXPECT_EQ(v, varying_floats / 4);
  GLboolean compiler = GL_FALSE;
  glGetBooleanv(GL_SHADER_COMPILER, &compiler);
  EXPECT_EQ(compiler, GL_TRUE);
  glGetIntegerv(GL_NUM_SHADER_BINARY_FORMATS, &v);
  EXPECT_EQ(v, 0);
  glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_FORMAT, &v);
  EXPECT_EQ(v, GL_RGBA);
  glGetIntegerv(GL_IMPLEMENTATION_COLOR_READ_TYPE, &v);
  EXPECT_EQ(v, GL_UNSIGNED_BYTE);
  glGetIntegerv(GL_MAX_CLIP_PLANES, &v);
  EXPECT_EQ(v, 6);  // desktop GL's, not ES 2.0's 0
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  GLint range[2] = {0, 0}, precision = -1;
  glGetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT, range, &precision);
  EXPECT_EQ(range[0], 127);
  EXPECT_EQ(range[1], 127);
  EXPECT_EQ(precision, 23);
  glGetShaderPrecisionFormat(GL_VERTEX_SHADER, GL_MEDIUM_INT, range, &precision);
  EXPECT_EQ(range[0], 24);
  EXPECT_EQ(precision, 0);
  glGetShaderPrecisionFormat(GL_TEXTURE_2D, GL_HIGH_FLOAT, range, &precision);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glReleaseShaderCompiler();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const GLuint shader = glCreateShader(GL_VERTEX_SHADER);
  glShaderBinary(1, &shader, GL_NONE, "", 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));  // no binary formats
  glShaderBinary(-1, &shader, GL_NONE, "", 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDeleteShader(shader);
}

TEST_F(Es2CompatibilityTest, FloatDepthCallsCompileIntoLists) {
  glDepthRangef(0.25f, 0.75f);
  GLfloat range[2] = {};
  glGetFloatv(GL_DEPTH_RANGE, range);
  EXPECT_FLOAT_EQ(range[0], 0.25f);
  EXPECT_FLOAT_EQ(range[1], 0.75f);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glClearDepthf(0.5f);
  glDepthRangef(0.0f, 0.5f);
  glEndList();
  GLfloat clear = -1.0f;
  glGetFloatv(GL_DEPTH_CLEAR_VALUE, &clear);
  EXPECT_FLOAT_EQ(clear, 1.0f);  // compiled, not executed
  glCallList(list);
  glGetFloatv(GL_DEPTH_CLEAR_VALUE, &clear);
  EXPECT_FLOAT_EQ(clear, 0.5f);
  glGetFloatv(GL_DEPTH_RANGE, range);
  EXPECT_FLOAT_EQ(range[1], 0.5f);
  glDeleteLists(list, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A GL_FIXED (16.16) generic array: the positions 1.0 and -1.0 cover the whole window.
TEST_F(Es2CompatibilityTest, FixedPointGenericArray) {
  const GLuint program = link("attribute vec2 position; void main() { gl_Position = vec4(position, 0.0, 1.0); }",
                              "void main() { gl_FragColor = vec4(0.0, 1.0, 0.0, 1.0); }");
  glBindAttribLocation(program, 0, "position");
  glLinkProgram(program);
  ASSERT_EQ(program_int(program, GL_LINK_STATUS), GL_TRUE) << program_log(program);
  glUseProgram(program);
  const GLfixed one = 1 << 16;
  const GLfixed corners[] = {-one, -one, one, -one, one, one, -one, one};
  glVertexAttribPointer(0, 2, GL_FIXED, GL_FALSE, 0, corners);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint type = 0;
  glGetVertexAttribiv(0, GL_VERTEX_ATTRIB_ARRAY_TYPE, &type);
  EXPECT_EQ(type, GL_FIXED);
  glEnableVertexAttribArray(0);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(pixel(width() - 1, height() - 1), (Rgba{0, 255, 0, 255}));
  glDisableVertexAttribArray(0);
  glUseProgram(0);
  glDeleteProgram(program);
}

// A depth-only framebuffer whose draw and read buffers still name COLOR_ATTACHMENT0 is
// complete through both entry points, and depth-tested draws write its depth.
TEST_F(Es2CompatibilityTest, DepthOnlyFramebufferIsComplete) {
  GLuint depth = 0, fb = 0;
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 8, 8);
  glGenFramebuffers(1, &fb);
  glBindFramebuffer(GL_FRAMEBUFFER, fb);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  EXPECT_EQ(glCheckFramebufferStatusEXT(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, 8, 8);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glBegin(GL_QUADS);  // window depth 0.25
  glVertex3f(-1, -1, -0.5f); glVertex3f(1, -1, -0.5f); glVertex3f(1, 1, -0.5f); glVertex3f(-1, 1, -0.5f);
  glEnd();
  GLuint z = 0;
  glReadPixels(3, 3, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_NEAR(double(z) / 4294967295.0, 0.25, 1e-6);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &fb);
  glDeleteRenderbuffers(1, &depth);
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// GLSL ES 1.00 shaders compile and link in a desktop context.
TEST_F(Es2CompatibilityTest, GlslEs100Shaders) {
  const GLuint program = link("#version 100\nattribute vec4 position; void main() { gl_Position = position; }\n",
                              "#version 100\nprecision mediump float;\n"
                              "void main() { gl_FragColor = vec4(1.0, 0.0, 1.0, 1.0); }\n");
  glBindAttribLocation(program, 0, "position");
  glLinkProgram(program);
  ASSERT_EQ(program_int(program, GL_LINK_STATUS), GL_TRUE) << program_log(program);
  glUseProgram(program);
  const GLfloat corners[] = {-1, -1, 1, -1, 1, 1, -1, 1};
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, corners);
  glEnableVertexAttribArray(0);
  glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
  EXPECT_EQ(pixel(1, 1), (Rgba{255, 0, 255, 255}));
  glDisableVertexAttribArray(0);
  glUseProgram(0);
  glDeleteProgram(program);
  // Not mixed with desktop GLSL in one program.
  const GLuint mixed = link("#version 100\nattribute vec4 position; void main() { gl_Position = position; }\n",
                            "#version 110\nvoid main() { gl_FragColor = vec4(1.0); }\n");
  EXPECT_EQ(program_int(mixed, GL_LINK_STATUS), GL_FALSE);
  EXPECT_NE(program_log(mixed).find("cannot be linked together"), std::string::npos) << program_log(mixed);
  glDeleteProgram(mixed);
  const GLuint es300 = compile(GL_FRAGMENT_SHADER, "#version 300 es\nvoid main() {}\n");
  EXPECT_EQ(shader_int(es300, GL_COMPILE_STATUS), GL_FALSE);
  glDeleteShader(es300);
}

// GL_RGB565 as a texture's internal format: 5, 6 and 5 bits.
TEST_F(Es2CompatibilityTest, Rgb565Textures) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  const GLubyte texel[4] = {255, 128, 0, 255};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB565, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLint bits[3] = {};
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &bits[0]);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_GREEN_SIZE, &bits[1]);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_BLUE_SIZE, &bits[2]);
  EXPECT_EQ(bits[0], 5);
  EXPECT_EQ(bits[1], 6);
  EXPECT_EQ(bits[2], 5);
  GLint format = 0;
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  EXPECT_EQ(format, GL_RGB565);
  glDeleteTextures(1, &texture);
}

}  // namespace
}  // namespace pineda::test
