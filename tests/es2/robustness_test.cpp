// GL_KHR_robustness and GL_EXT_robustness in OpenGL ES 2.0: the _KHR and _EXT names (through
// libGLESv2 and eglGetProcAddress) share GL_ARB_robustness's getters, which write nothing past
// bufSize; the context reports the robustness EGL_EXT_create_context_robustness asked for.
#define GL_GLEXT_PROTOTYPES
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "tests/e2e/support/bounded_write.h"
#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

using test::kGuard;
using test::written;

// An ES 2.0 context made with EGL_EXT_create_context_robustness's attributes.
struct RobustEs2Context : es1_test::EglContext {
  explicit RobustEs2Context(const EGLint* attribs) : EglContext(EGL_OPENGL_ES_API, attribs, 4, 4, EGL_OPENGL_ES2_BIT) {}
  ~RobustEs2Context() { eglBindAPI(EGL_OPENGL_API); }
};

constexpr EGLint kRobustLoseOnReset[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_CONTEXT_OPENGL_ROBUST_ACCESS_EXT, EGL_TRUE,
                                         EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT,
                                         EGL_LOSE_CONTEXT_ON_RESET_EXT, EGL_NONE};

template <typename F>
F proc(const char* name) {
  return reinterpret_cast<F>(eglGetProcAddress(name));
}

// `robust` given exactly `expected.size()` bytes writes `expected`; one byte less records
// GL_INVALID_OPERATION and writes nothing.
template <typename Robust>
void expect_bounded(const std::vector<uint8_t>& expected, Robust robust) {
  const size_t needed = expected.size();
  EXPECT_EQ(written(needed, [&](void* p) { robust(GLsizei(needed), p); }), expected);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(written(needed - 1, [&](void* p) { robust(GLsizei(needed - 1), p); }),
            std::vector<uint8_t>(needed - 1, kGuard));
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
}

template <typename T>
std::vector<uint8_t> bytes_of(std::initializer_list<T> values) {
  std::vector<uint8_t> out(values.size() * sizeof(T));
  std::memcpy(out.data(), values.begin(), out.size());
  return out;
}

TEST(Es2Robustness, AdvertisedWithEveryFunction) {
  Es2Context context(4, 4);
  ASSERT_TRUE(context.ok()) << context.error();
  const std::string extensions = " " + std::string(reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS)));
  EXPECT_NE(extensions.find(" GL_KHR_robustness "), std::string::npos);
  EXPECT_NE(extensions.find(" GL_EXT_robustness "), std::string::npos);
  for (const char* name : {"glGetGraphicsResetStatusKHR", "glReadnPixelsKHR", "glGetnUniformfvKHR", "glGetnUniformivKHR",
                           "glGetnUniformuivKHR", "glGetGraphicsResetStatusEXT", "glReadnPixelsEXT",
                           "glGetnUniformfvEXT", "glGetnUniformivEXT"})
    EXPECT_NE(eglGetProcAddress(name), nullptr) << name;
  // The exported symbols are the same functions.
  EXPECT_EQ(eglGetProcAddress("glReadnPixelsKHR"), reinterpret_cast<void (*)()>(&glReadnPixelsKHR));
  EXPECT_EQ(eglGetProcAddress("glGetnUniformfvEXT"), reinterpret_cast<void (*)()>(&glGetnUniformfvEXT));
}

TEST(Es2Robustness, DefaultContextIsNotRobustAndNeverReset) {
  Es2Context context(4, 4);
  ASSERT_TRUE(context.ok()) << context.error();
  GLint robust = -1, strategy = -1;
  glGetIntegerv(GL_CONTEXT_ROBUST_ACCESS_KHR, &robust);
  glGetIntegerv(GL_RESET_NOTIFICATION_STRATEGY_KHR, &strategy);
  EXPECT_EQ(robust, GL_FALSE);
  EXPECT_EQ(strategy, GL_NO_RESET_NOTIFICATION_KHR);
  EXPECT_EQ(glGetGraphicsResetStatusKHR(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(glGetGraphicsResetStatusEXT(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(Es2Robustness, RobustContextReportsWhatEglAsked) {
  RobustEs2Context context(kRobustLoseOnReset);
  ASSERT_TRUE(context.ok()) << context.error();
  GLboolean robust = GL_FALSE;
  GLint strategy = -1;
  glGetBooleanv(GL_CONTEXT_ROBUST_ACCESS_EXT, &robust);
  glGetIntegerv(GL_RESET_NOTIFICATION_STRATEGY_EXT, &strategy);
  EXPECT_EQ(robust, GL_TRUE);
  EXPECT_EQ(strategy, GL_LOSE_CONTEXT_ON_RESET_EXT);
  // Lost on reset, but a software context is never reset.
  EXPECT_EQ(glGetGraphicsResetStatusKHR(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST(Es2Robustness, ReadnPixelsWritesNothingPastBufSize) {
  RobustEs2Context context(kRobustLoseOnReset);
  ASSERT_TRUE(context.ok()) << context.error();
  glClearColor(1, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  std::vector<uint8_t> magenta;
  for (int i = 0; i < 2 * 3; ++i) magenta.insert(magenta.end(), {255, 0, 255, 255});
  for (auto read : {proc<PFNGLREADNPIXELSKHRPROC>("glReadnPixelsKHR"), proc<PFNGLREADNPIXELSKHRPROC>("glReadnPixelsEXT")}) {
    ASSERT_NE(read, nullptr);
    expect_bounded(magenta, [&](GLsizei n, void* p) { read(0, 0, 2, 3, GL_RGBA, GL_UNSIGNED_BYTE, n, p); });
    // A negative bufSize holds nothing.
    read(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, -1, nullptr);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
    // The errors of glReadPixels come first.
    uint8_t pixel[4];
    read(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 4, pixel);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  }
}

TEST(Es2Robustness, GetnUniformsWriteNothingPastBufSize) {
  Es2Context context(4, 4);
  ASSERT_TRUE(context.ok()) << context.error();
  const GLuint program = build_program("uniform vec3 v; uniform ivec2 i; "
                                       "void main() { gl_Position = vec4(v, float(i.x + i.y)); }",
                                       "void main() { gl_FragColor = vec4(1.0); }", {});
  ASSERT_NE(program, 0u);
  glUseProgram(program);
  const GLint v = glGetUniformLocation(program, "v");
  const GLint i = glGetUniformLocation(program, "i");
  glUniform3f(v, 1.5f, -2.0f, 7.0f);
  glUniform2i(i, -3, 9);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  for (const char* suffix : {"KHR", "EXT"}) {
    SCOPED_TRACE(suffix);
    auto getf = proc<PFNGLGETNUNIFORMFVKHRPROC>(("glGetnUniformfv" + std::string(suffix)).c_str());
    auto geti = proc<PFNGLGETNUNIFORMIVKHRPROC>(("glGetnUniformiv" + std::string(suffix)).c_str());
    ASSERT_TRUE(getf && geti);
    expect_bounded(bytes_of<GLfloat>({1.5f, -2.0f, 7.0f}),
                   [&](GLsizei n, void* p) { getf(program, v, n, static_cast<GLfloat*>(p)); });
    expect_bounded(bytes_of<GLint>({-3, 9}), [&](GLsizei n, void* p) { geti(program, i, n, static_cast<GLint*>(p)); });
    // Floats convert to the nearest integer.
    expect_bounded(bytes_of<GLint>({2, -2, 7}), [&](GLsizei n, void* p) { geti(program, v, n, static_cast<GLint*>(p)); });
  }
  // GL_KHR_robustness's unsigned getter: ES 2.0 has no unsigned uniforms; the others convert as
  // to int and keep their bits.
  expect_bounded(bytes_of<GLuint>({GLuint(-3), 9u}),
                 [&](GLsizei n, void* p) { glGetnUniformuivKHR(program, i, n, static_cast<GLuint*>(p)); });
  expect_bounded(bytes_of<GLuint>({2u, GLuint(-2), 7u}),
                 [&](GLsizei n, void* p) { glGetnUniformuivKHR(program, v, n, static_cast<GLuint*>(p)); });
  // The errors of glGetUniform come first: a location the program does not have.
  GLfloat out[4];
  glGetnUniformfvKHR(program, 99, sizeof(out), out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glGetnUniformfvKHR(12345, v, sizeof(out), out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glUseProgram(0);
  glDeleteProgram(program);
}

TEST(Es2Robustness, DesktopNamesAreNotOpenGlEsCommands) {
  Es2Context context(4, 4);
  ASSERT_TRUE(context.ok()) << context.error();
  uint8_t pixel[4] = {kGuard, kGuard, kGuard, kGuard};
  auto read_arb = proc<PFNGLREADNPIXELSKHRPROC>("glReadnPixelsARB");
  auto read_core = proc<PFNGLREADNPIXELSKHRPROC>("glReadnPixels");
  ASSERT_TRUE(read_arb && read_core);
  for (auto read : {read_arb, read_core}) {
    read(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 4, pixel);
    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
    EXPECT_EQ(pixel[0], kGuard);
  }
}

}  // namespace
}  // namespace pineda::es2_test
