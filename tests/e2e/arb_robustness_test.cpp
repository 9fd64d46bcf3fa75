// GL_ARB_robustness (and GL_KHR_robustness's desktop names): the context is never reset, and every glGetn*/glReadn* getter writes
// exactly what its plain form writes when bufSize holds it, and nothing (GL_INVALID_OPERATION)
// when it does not; with a pixel pack buffer bound, bufSize does not limit the pixels.
#define GL_GLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstring>
#include <string>
#include <vector>

#include "tests/e2e/support/bounded_write.h"
#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class ArbRobustnessTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {.width = 8, .height = 4}; }

  // A linked program of one vertex shader, in use.
  GLuint vertex_program(const char* source) {
    GLuint shader = glCreateShader(GL_VERTEX_SHADER);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLuint program = glCreateProgram();
    glAttachShader(program, shader);
    glLinkProgram(program);
    glDeleteShader(shader);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    EXPECT_TRUE(linked);
    glUseProgram(program);
    return program;
  }

  // A getter given exactly the size it needs writes what the plain call writes; one byte less
  // records GL_INVALID_OPERATION and writes nothing.
  template <typename Plain, typename Robust>
  void expect_bounded(size_t needed, Plain plain, Robust robust) {
    const std::vector<uint8_t> expected = written(needed, plain);
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    EXPECT_EQ(written(needed, [&](void* p) { robust(GLsizei(needed), p); }), expected);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    EXPECT_EQ(written(needed - 1, [&](void* p) { robust(GLsizei(needed - 1), p); }),
              std::vector<uint8_t>(needed - 1, kGuard));
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
    robust(-1, nullptr);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  }
};

TEST_F(ArbRobustnessTest, AdvertisedAndNeverReset) {
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(extensions.find("GL_ARB_robustness "), std::string::npos);
  EXPECT_EQ(glGetGraphicsResetStatusARB(), GLenum(GL_NO_ERROR));
  GLint strategy = 0;
  glGetIntegerv(GL_RESET_NOTIFICATION_STRATEGY_ARB, &strategy);
  EXPECT_EQ(strategy, GL_NO_RESET_NOTIFICATION_ARB);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ArbRobustnessTest, ReadnPixels) {
  clear_to(1, 0.5f, 0, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 8);  // rows of 3 x 3 bytes padded to 16: the last one is not
  expect_bounded(16 * 3 + 9, [](void* p) { glReadPixels(0, 0, 3, 4, GL_RGB, GL_UNSIGNED_BYTE, p); },
                 [](GLsizei n, void* p) { glReadnPixelsARB(0, 0, 3, 4, GL_RGB, GL_UNSIGNED_BYTE, n, p); });
  // Errors of the plain call come first.
  uint8_t none[4];
  glReadnPixelsARB(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 4, none);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(ArbRobustnessTest, ReadnPixelsIntoAPackBufferIgnoresBufSize) {
  clear_to(0, 1, 0, 1);
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, buffer);
  glBufferData(GL_PIXEL_PACK_BUFFER, 64, nullptr, GL_STREAM_READ);
  glReadnPixelsARB(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, 0, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  uint8_t pixel[4] = {};
  glGetBufferSubData(GL_PIXEL_PACK_BUFFER, 60, 4, pixel);
  EXPECT_EQ(pixel[1], 255);
  // The buffer's own size still bounds what is written.
  glReadnPixelsARB(0, 0, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, 1 << 20, nullptr);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glDeleteBuffers(1, &buffer);
}

TEST_F(ArbRobustnessTest, GetnTexImage) {
  std::vector<uint8_t> texels(5 * 3 * 4);
  for (size_t i = 0; i < texels.size(); ++i) texels[i] = uint8_t(i * 7);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 5, 3, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  expect_bounded(texels.size(), [](void* p) { glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, p); },
                 [](GLsizei n, void* p) { glGetnTexImageARB(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, n, p); });
  EXPECT_EQ(written(texels.size(), [](void* p) { glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, p); }),
            texels);
}

TEST_F(ArbRobustnessTest, GetnPolygonStipple) {
  GLubyte pattern[128];
  for (int i = 0; i < 128; ++i) pattern[i] = GLubyte(i * 13 + 1);
  glPolygonStipple(pattern);
  expect_bounded(128, [](void* p) { glGetPolygonStipple(static_cast<GLubyte*>(p)); },
                 [](GLsizei n, void* p) { glGetnPolygonStippleARB(n, static_cast<GLubyte*>(p)); });
}

TEST_F(ArbRobustnessTest, GetnPixelMaps) {
  const GLfloat map[3] = {0.25f, 0.5f, 1.0f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 3, map);
  expect_bounded(3 * sizeof(GLfloat), [](void* p) { glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, static_cast<GLfloat*>(p)); },
                 [](GLsizei n, void* p) { glGetnPixelMapfvARB(GL_PIXEL_MAP_R_TO_R, n, static_cast<GLfloat*>(p)); });
  expect_bounded(3 * sizeof(GLuint), [](void* p) { glGetPixelMapuiv(GL_PIXEL_MAP_R_TO_R, static_cast<GLuint*>(p)); },
                 [](GLsizei n, void* p) { glGetnPixelMapuivARB(GL_PIXEL_MAP_R_TO_R, n, static_cast<GLuint*>(p)); });
  expect_bounded(3 * sizeof(GLushort),
                 [](void* p) { glGetPixelMapusv(GL_PIXEL_MAP_R_TO_R, static_cast<GLushort*>(p)); },
                 [](GLsizei n, void* p) { glGetnPixelMapusvARB(GL_PIXEL_MAP_R_TO_R, n, static_cast<GLushort*>(p)); });
}

TEST_F(ArbRobustnessTest, GetnMaps) {
  const GLfloat points[3 * 4] = {0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  glMap1f(GL_MAP1_VERTEX_3, 0, 1, 3, 4, points);
  expect_bounded(12 * sizeof(GLdouble),
                 [](void* p) { glGetMapdv(GL_MAP1_VERTEX_3, GL_COEFF, static_cast<GLdouble*>(p)); },
                 [](GLsizei n, void* p) { glGetnMapdvARB(GL_MAP1_VERTEX_3, GL_COEFF, n, static_cast<GLdouble*>(p)); });
  expect_bounded(2 * sizeof(GLfloat), [](void* p) { glGetMapfv(GL_MAP1_VERTEX_3, GL_DOMAIN, static_cast<GLfloat*>(p)); },
                 [](GLsizei n, void* p) { glGetnMapfvARB(GL_MAP1_VERTEX_3, GL_DOMAIN, n, static_cast<GLfloat*>(p)); });
  expect_bounded(sizeof(GLint), [](void* p) { glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, static_cast<GLint*>(p)); },
                 [](GLsizei n, void* p) { glGetnMapivARB(GL_MAP1_VERTEX_3, GL_ORDER, n, static_cast<GLint*>(p)); });
  GLint v = 0;
  glGetnMapivARB(GL_MAP1_VERTEX_3, GL_TEXTURE_2D, 4, &v);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
}

TEST_F(ArbRobustnessTest, GetnUniforms) {
  const GLuint program = vertex_program("uniform vec3 v; void main() { gl_Position = vec4(v, 1.0); }");
  const GLint location = glGetUniformLocation(program, "v");
  glUniform3f(location, 1.5f, -2.0f, 7.0f);
  expect_bounded(3 * sizeof(GLfloat), [&](void* p) { glGetUniformfv(program, location, static_cast<GLfloat*>(p)); },
                 [&](GLsizei n, void* p) { glGetnUniformfvARB(program, location, n, static_cast<GLfloat*>(p)); });
  expect_bounded(3 * sizeof(GLint), [&](void* p) { glGetUniformiv(program, location, static_cast<GLint*>(p)); },
                 [&](GLsizei n, void* p) { glGetnUniformivARB(program, location, n, static_cast<GLint*>(p)); });
  glUseProgram(0);
  glDeleteProgram(program);
}

// GL_KHR_robustness on desktop GL: GL 4.5's unsuffixed names run the same getters.
TEST_F(ArbRobustnessTest, KhrRobustnessNames) {
  const std::string extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  EXPECT_NE(extensions.find("GL_KHR_robustness "), std::string::npos);
  EXPECT_EQ(glGetGraphicsResetStatus(), GLenum(GL_NO_ERROR));
  GLboolean robust = GL_TRUE;
  glGetBooleanv(GL_CONTEXT_ROBUST_ACCESS, &robust);  // the fixture asks for no robust access
  EXPECT_EQ(robust, GL_FALSE);
  GLint strategy = 0;
  glGetIntegerv(GL_RESET_NOTIFICATION_STRATEGY, &strategy);
  EXPECT_EQ(strategy, GL_NO_RESET_NOTIFICATION);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

  clear_to(0, 1, 0, 1);
  expect_bounded(2 * 2 * 4, [](void* p) { glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, p); },
                 [](GLsizei n, void* p) { glReadnPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, n, p); });

  const GLuint program = vertex_program("uniform vec2 v; void main() { gl_Position = vec4(v, 0.0, 1.0); }");
  const GLint location = glGetUniformLocation(program, "v");
  glUniform2f(location, -1.0f, 3.25f);
  expect_bounded(2 * sizeof(GLfloat), [&](void* p) { glGetUniformfv(program, location, static_cast<GLfloat*>(p)); },
                 [&](GLsizei n, void* p) { glGetnUniformfv(program, location, n, static_cast<GLfloat*>(p)); });
  expect_bounded(2 * sizeof(GLint), [&](void* p) { glGetUniformiv(program, location, static_cast<GLint*>(p)); },
                 [&](GLsizei n, void* p) { glGetnUniformiv(program, location, n, static_cast<GLint*>(p)); });
  // No unsigned uniforms in GL 2.1: a float converts as to int, and keeps its bits.
  GLuint u[2] = {};
  glGetnUniformuiv(program, location, sizeof(u), u);
  EXPECT_EQ(u[0], GLuint(-1));
  EXPECT_EQ(u[1], 3u);
  expect_bounded(2 * sizeof(GLuint), [&](void* p) { glGetnUniformuiv(program, location, sizeof(u), static_cast<GLuint*>(p)); },
                 [&](GLsizei n, void* p) { glGetnUniformuiv(program, location, n, static_cast<GLuint*>(p)); });
  glUseProgram(0);
  glDeleteProgram(program);
}

// The OpenGL ES names (_KHR, _EXT) are not desktop GL commands.
TEST_F(ArbRobustnessTest, EsNamesAreRefused) {
  uint8_t pixel[4] = {kGuard, kGuard, kGuard, kGuard};
  auto read = reinterpret_cast<PFNGLREADNPIXELSPROC>(eglGetProcAddress("glReadnPixelsKHR"));
  ASSERT_NE(read, nullptr);
  read(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 4, pixel);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(pixel[0], kGuard);
}

TEST_F(ArbRobustnessTest, GetnCompressedTexImageOfAnUncompressedLevel) {
  const uint8_t texel[4] = {1, 2, 3, 4};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  uint8_t out[4] = {kGuard, kGuard, kGuard, kGuard};
  glGetnCompressedTexImageARB(GL_TEXTURE_2D, 0, 4, out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(out[0], kGuard);
}

}  // namespace
}  // namespace pineda::test
