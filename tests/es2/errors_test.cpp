// The errors ES 2.0 gives where desktop GL 2.0 would act: commands it lacks
// (INVALID_OPERATION), enums it lacks (INVALID_ENUM), its texture and renderbuffer format
// rules, shader binaries and the precision query.
#include <gtest/gtest.h>

#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

class Es2Errors : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(context.ok()) << context.error();
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  }
  Es2Context context{8, 8};
};

template <typename F>
F proc(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

// Fixed-function and desktop-only calls exist in the library (desktop GL contexts use them)
// but an ES 2.0 context refuses them.
TEST_F(Es2Errors, FixedFunctionCallsAreInvalidOperation) {
  using Enum1 = void (*)(GLenum);
  using Void0 = void (*)();
  using Float4 = void (*)(GLfloat, GLfloat, GLfloat, GLfloat);
  using Ptr = void (*)(GLint, GLenum, GLsizei, const void*);
  auto matrix_mode = proc<Enum1>("glMatrixMode");
  auto load_identity = proc<Void0>("glLoadIdentity");
  auto begin = proc<Enum1>("glBegin");
  auto color4f = proc<Float4>("glColor4f");
  auto vertex_pointer = proc<Ptr>("glVertexPointer");
  auto enable_client_state = proc<Enum1>("glEnableClientState");
  auto orthof = proc<void (*)(GLfloat, GLfloat, GLfloat, GLfloat, GLfloat, GLfloat)>("glOrthof");
  ASSERT_TRUE(matrix_mode && load_identity && begin && color4f && vertex_pointer && enable_client_state && orthof);
  matrix_mode(0x1700 /* GL_MODELVIEW */);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  load_identity();
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  begin(GL_TRIANGLES);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  color4f(1, 0, 0, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  vertex_pointer(2, GL_FLOAT, 0, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  enable_client_state(0x8074 /* GL_VERTEX_ARRAY */);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  orthof(0, 1, 0, 1, 0, 1);  // ES 1.1 only
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(Es2Errors, EnumsOutsideES2AreInvalidEnum) {
  glEnable(GL_TEXTURE_2D);  // an ES 2.0 enum, but not a capability there
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glEnable(0x0B50 /* GL_LIGHTING */);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_2D), GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glEnable(GL_BLEND);
  EXPECT_EQ(glIsEnabled(GL_BLEND), GL_TRUE);
  GLint v = -7;
  glGetIntegerv(0x0BA0 /* GL_MATRIX_MODE */, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(v, -7);
  // MAX_CLIP_DISTANCES_EXT's value, which piglit's shader_runner_gles2 asks for: 0, no error.
  glGetIntegerv(0x0D32 /* GL_MAX_CLIP_PLANES */, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(v, 0);
  glBindTexture(0x0DE0 /* GL_TEXTURE_1D */, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glDrawArrays(0x0007 /* GL_QUADS */, 0, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(glGetString(0x1F04), nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, 0x2900 /* GL_CLAMP */);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, 0x1004 /* GL_TEXTURE_BORDER_COLOR */, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Es2Errors, TextureFormatRules) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  const uint8_t pixels[64] = {};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // internalformat != format
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // not a pair of table 3.4
  glTexImage2D(GL_TEXTURE_2D, 0, 0x8058 /* GL_RGBA8 */, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));  // sized internal formats are ES 3.0's
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));  // border
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_FLOAT, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_BGRA_EXT, 2, 2, 0, GL_BGRA_EXT, GL_UNSIGNED_BYTE, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 3, 5, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, pixels);  // NPOT
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGB, GL_UNSIGNED_SHORT_5_5_5_1, pixels);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 0, 0, 2, 2, 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 0, 0, 2, 2, 1);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(Es2Errors, ReadPixelsTakesRgbaUnsignedByte) {
  uint8_t pixel[8] = {};
  glReadPixels(0, 0, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_FLOAT, pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Es2Errors, RenderbufferFormats) {
  GLuint rb = 0;
  glGenRenderbuffers(1, &rb);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA, 4, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  for (GLenum format : {GL_RGBA4, GL_RGB5_A1, GL_RGB565, GL_DEPTH_COMPONENT16, GL_STENCIL_INDEX8, GL_RGB8_OES,
                        GL_RGBA8_OES, GL_DEPTH_COMPONENT24_OES, GL_DEPTH24_STENCIL8_OES}) {
    glRenderbufferStorage(GL_RENDERBUFFER, format, 4, 4);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << std::hex << format;
  }
}

TEST_F(Es2Errors, ShaderBinaryHasNoFormats) {
  const GLuint shader = glCreateShader(GL_VERTEX_SHADER);
  const char data[4] = {};
  glShaderBinary(1, &shader, 0, data, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glShaderBinary(-1, &shader, 0, data, 4);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glReleaseShaderCompiler();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  // The compiler still works after a release.
  const char* source = "void main() { gl_Position = vec4(0.0); }";
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint status = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &status);
  EXPECT_EQ(status, GL_TRUE);
}

TEST_F(Es2Errors, ShaderPrecisionFormat) {
  GLint range[2] = {-1, -1}, precision = -1;
  glGetShaderPrecisionFormat(GL_FRAGMENT_SHADER, GL_HIGH_FLOAT, range, &precision);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(range[0], 127);
  EXPECT_EQ(range[1], 127);
  EXPECT_EQ(precision, 23);
  glGetShaderPrecisionFormat(GL_VERTEX_SHADER, GL_LOW_INT, range, &precision);
  EXPECT_EQ(range[0], 24);
  EXPECT_EQ(range[1], 24);
  EXPECT_EQ(precision, 0);
  glGetShaderPrecisionFormat(GL_VERTEX_SHADER, GL_VERTEX_SHADER, range, &precision);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glGetShaderPrecisionFormat(GL_HIGH_FLOAT, GL_HIGH_FLOAT, range, &precision);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

// GLSL ES 1.00 rules: a fragment shader without a default float precision does not compile;
// desktop GLSL versions are refused; a program needs both stages.
TEST_F(Es2Errors, ShadersAreGlslEs100) {
  auto compiles = [](GLenum type, const char* source) {
    const GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    GLint status = -1;
    glGetShaderiv(s, GL_COMPILE_STATUS, &status);
    glDeleteShader(s);
    return status;
  };
  EXPECT_EQ(compiles(GL_FRAGMENT_SHADER, "void main() { float x = 1.0; gl_FragColor = vec4(x); }"), GL_FALSE);
  EXPECT_EQ(compiles(GL_FRAGMENT_SHADER, "precision mediump float; void main() { float x = 1.0; gl_FragColor = vec4(x); }"),
            GL_TRUE);
  EXPECT_EQ(compiles(GL_VERTEX_SHADER, "#version 120\nvoid main() { gl_Position = vec4(0.0); }"), GL_FALSE);
  EXPECT_EQ(compiles(GL_VERTEX_SHADER, "#version 100\nvoid main() { gl_Position = gl_Vertex; }"), GL_FALSE);
  EXPECT_EQ(compiles(GL_FRAGMENT_SHADER,
                     "#extension GL_OES_standard_derivatives : require\nprecision mediump float;\n"
                     "void main() { gl_FragColor = vec4(dFdx(gl_FragCoord.x)); }"),
            GL_TRUE);
  const GLuint vs = glCreateShader(GL_VERTEX_SHADER), vs2 = glCreateShader(GL_VERTEX_SHADER);
  const char* source = "void main() { gl_Position = vec4(0.0); }";
  glShaderSource(vs, 1, &source, nullptr);
  glCompileShader(vs);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, vs2);  // ES 2.0: one shader of each type
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glLinkProgram(program);
  GLint linked = -1;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  EXPECT_EQ(linked, GL_FALSE);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::es2_test

namespace pineda::es2_test {
namespace {

TEST(Es2Extensions, DiscardFramebufferErrorsAndContents) {
  Es2Context context(4, 4);
  ASSERT_TRUE(context.ok()) << context.error();
  auto discard = reinterpret_cast<PFNGLDISCARDFRAMEBUFFEREXTPROC>(eglGetProcAddress("glDiscardFramebufferEXT"));
  ASSERT_NE(discard, nullptr);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const GLenum window[] = {GL_COLOR_EXT, GL_DEPTH_EXT, GL_STENCIL_EXT};
  discard(GL_FRAMEBUFFER, 3, window);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(read_pixel(1, 1), 0x00FF00FFu);  // a hint: the contents stay
  discard(GL_RENDERBUFFER, 1, window);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  discard(GL_FRAMEBUFFER, -1, window);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  const GLenum attachment[] = {GL_COLOR_ATTACHMENT0};
  discard(GL_FRAMEBUFFER, 1, attachment);  // an object's name while the window is bound
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  GLuint fbo = 0;
  glGenFramebuffers(1, &fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  discard(GL_FRAMEBUFFER, 1, attachment);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  discard(GL_FRAMEBUFFER, 1, window);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

// GLSL ES 1.00 4.6.4: gl_FragCoord invariant needs gl_Position invariant; gl_PointCoord needs
// gl_PointSize; gl_FrontFacing never.
TEST(Es2Extensions, InvariantBuiltinsLinkage) {
  Es2Context context(4, 4);
  ASSERT_TRUE(context.ok()) << context.error();
  const char* plain_vs = "void main() { gl_PointSize = 1.0; gl_Position = vec4(0.0); }";
  const char* invariant_vs = "invariant gl_Position; void main() { gl_Position = vec4(0.0); }";
  const char* fragcoord_fs =
      "invariant gl_FragCoord; precision mediump float; void main() { gl_FragColor = vec4(gl_FragCoord.x); }";
  const char* pointcoord_fs =
      "invariant gl_PointCoord; precision mediump float; void main() { gl_FragColor = vec4(gl_PointCoord.x); }";
  const char* plain_fs = "precision mediump float; void main() { gl_FragColor = vec4(gl_FragCoord.x); }";
  EXPECT_EQ(build_program(plain_vs, fragcoord_fs, {}), 0u);
  EXPECT_NE(build_program(invariant_vs, fragcoord_fs, {}), 0u);
  EXPECT_EQ(build_program(plain_vs, pointcoord_fs, {}), 0u);
  EXPECT_NE(build_program(plain_vs, plain_fs, {}), 0u);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::es2_test
