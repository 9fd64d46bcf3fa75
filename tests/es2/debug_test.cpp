// GL_KHR_debug in OpenGL ES 2.0: the _KHR-suffixed names reach the same message log.
#include <gtest/gtest.h>

#include <string>

#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

TEST(Es2Debug, KhrNamesInsertAndReadTheLog) {
  Es2Context context(4, 4);
  ASSERT_TRUE(context.ok()) << context.error();
  auto insert = reinterpret_cast<PFNGLDEBUGMESSAGEINSERTKHRPROC>(eglGetProcAddress("glDebugMessageInsertKHR"));
  auto get_log = reinterpret_cast<PFNGLGETDEBUGMESSAGELOGKHRPROC>(eglGetProcAddress("glGetDebugMessageLogKHR"));
  auto push = reinterpret_cast<PFNGLPUSHDEBUGGROUPKHRPROC>(eglGetProcAddress("glPushDebugGroupKHR"));
  auto pop = reinterpret_cast<PFNGLPOPDEBUGGROUPKHRPROC>(eglGetProcAddress("glPopDebugGroupKHR"));
  ASSERT_TRUE(insert && get_log && push && pop);
  glEnable(GL_DEBUG_OUTPUT_KHR);
  EXPECT_EQ(glIsEnabled(GL_DEBUG_OUTPUT_KHR), GL_TRUE);
  insert(GL_DEBUG_SOURCE_APPLICATION_KHR, GL_DEBUG_TYPE_MARKER_KHR, 42, GL_DEBUG_SEVERITY_NOTIFICATION_KHR, -1,
         "hello");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLenum source = 0, type = 0, severity = 0;
  GLuint id = 0;
  GLsizei length = 0;
  GLchar text[64] = {};
  ASSERT_EQ(get_log(1, sizeof(text), &source, &type, &id, &severity, &length, text), 1u);
  EXPECT_EQ(source, GLenum(GL_DEBUG_SOURCE_APPLICATION_KHR));
  EXPECT_EQ(id, 42u);
  EXPECT_EQ(std::string(text), "hello");
  push(GL_DEBUG_SOURCE_APPLICATION_KHR, 1, -1, "group");
  GLint depth = 0;
  glGetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH_KHR, &depth);
  EXPECT_EQ(depth, 2);
  pop();
  pop();  // the default group cannot be popped
  EXPECT_EQ(glGetError(), GLenum(GL_STACK_UNDERFLOW_KHR));
}

}  // namespace
}  // namespace pineda::es2_test

namespace pineda::es2_test {
namespace {

// Labels on the object kinds ES 2.0 programs use besides buffers and textures; a deleted
// object's label goes with it.
TEST(Es2Debug, LabelsOfShadersProgramsRenderbuffersFramebuffers) {
  Es2Context context(4, 4);
  ASSERT_TRUE(context.ok()) << context.error();
  auto label = reinterpret_cast<PFNGLOBJECTLABELKHRPROC>(eglGetProcAddress("glObjectLabelKHR"));
  auto get_label = reinterpret_cast<PFNGLGETOBJECTLABELKHRPROC>(eglGetProcAddress("glGetObjectLabelKHR"));
  ASSERT_TRUE(label && get_label);
  GLuint rb = 0, fb = 0;
  glGenRenderbuffers(1, &rb);
  glGenFramebuffers(1, &fb);
  const GLuint shader = glCreateShader(GL_FRAGMENT_SHADER), program = glCreateProgram();
  const struct {
    GLenum identifier;
    GLuint name;
  } objects[] = {{GL_SHADER_KHR, shader}, {GL_PROGRAM_KHR, program}, {GL_RENDERBUFFER, rb}, {GL_FRAMEBUFFER, fb}};
  for (const auto& o : objects) {
    label(o.identifier, o.name, -1, "named");
    GLchar text[16] = {};
    GLsizei length = -1;
    get_label(o.identifier, o.name, sizeof(text), &length, text);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << std::hex << o.identifier;
    EXPECT_EQ(std::string(text), "named");
    EXPECT_EQ(length, 5);
  }
  label(GL_SHADER_KHR, 999, -1, "x");
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glDeleteRenderbuffers(1, &rb);
  glGenRenderbuffers(1, &rb);  // may reuse the name: a new object without a label
  GLsizei length = -1;
  get_label(GL_RENDERBUFFER, rb, 0, &length, nullptr);
  EXPECT_EQ(length, 0);
}

}  // namespace
}  // namespace pineda::es2_test
