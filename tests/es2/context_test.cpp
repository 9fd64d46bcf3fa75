// ES 2.0 contexts through EGL on the surfaceless platform: both ways of asking for version 2,
// what the context reports, and current without any surface (EGL_KHR_surfaceless_context).
#include <gtest/gtest.h>

#include <string>

#include "tests/es2/es2_context.h"

namespace pineda::es2_test {
namespace {

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "<null>";
}

class Es2Egl : public ::testing::Test {
 protected:
  void SetUp() override {
    dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    ASSERT_NE(dpy, EGL_NO_DISPLAY);
    ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
    const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
    EGLint n = 0;
    ASSERT_TRUE(eglChooseConfig(dpy, attribs, &config, 1, &n));
    ASSERT_EQ(n, 1);
    ASSERT_TRUE(eglBindAPI(EGL_OPENGL_ES_API));
  }
  void TearDown() override {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    for (EGLContext c : contexts) eglDestroyContext(dpy, c);
    eglBindAPI(EGL_OPENGL_API);
  }
  EGLContext create(const EGLint* attribs) {
    EGLContext c = eglCreateContext(dpy, config, EGL_NO_CONTEXT, attribs);
    if (c != EGL_NO_CONTEXT) contexts.push_back(c);
    return c;
  }
  EGLDisplay dpy = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;
  std::vector<EGLContext> contexts;
};

TEST_F(Es2Egl, ClientVersion2IsES20) {
  const EGLint attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
  EGLContext ctx = create(attribs);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  EGLint value = 0;
  EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_CONTEXT_CLIENT_VERSION, &value));
  EXPECT_EQ(value, 2);
  EXPECT_TRUE(eglQueryContext(dpy, ctx, EGL_CONTEXT_CLIENT_TYPE, &value));
  EXPECT_EQ(value, EGL_OPENGL_ES_API);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(gl_string(GL_VERSION), "OpenGL ES 2.0 Pineda 0.1.0");
  EXPECT_EQ(gl_string(GL_SHADING_LANGUAGE_VERSION), "OpenGL ES GLSL ES 1.00");
  EXPECT_EQ(gl_string(GL_VENDOR), "Pineda");
  EXPECT_EQ(gl_string(GL_EXTENSIONS),
            "GL_EXT_blend_minmax GL_EXT_discard_framebuffer GL_EXT_draw_buffers GL_EXT_map_buffer_range GL_EXT_robustness "
            "GL_EXT_texture_format_BGRA8888 GL_KHR_debug GL_KHR_robustness GL_OES_depth24 GL_OES_depth_texture "
            "GL_OES_element_index_uint GL_OES_fbo_render_mipmap GL_OES_mapbuffer GL_OES_packed_depth_stencil "
            "GL_OES_rgb8_rgba8 GL_OES_standard_derivatives GL_OES_texture_npot GL_OES_vertex_array_object ");
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(Es2Egl, MajorVersion2IsES20AndES30IsNot) {
  const EGLint v20[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 0, EGL_NONE};
  EGLContext ctx = create(v20);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(gl_string(GL_VERSION), "OpenGL ES 2.0 Pineda 0.1.0");
  const EGLint v21[] = {EGL_CONTEXT_MAJOR_VERSION, 2, EGL_CONTEXT_MINOR_VERSION, 1, EGL_NONE};
  EXPECT_EQ(create(v21), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  const EGLint v30[] = {EGL_CONTEXT_CLIENT_VERSION, 3, EGL_NONE};
  EXPECT_EQ(create(v30), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
}

// The ES 2.0 context shares nothing with an ES 1.1 one made from the same config: each has
// its own API (GL_VERSION) while both exist.
TEST_F(Es2Egl, ES1AndES2ContextsSideBySide) {
  const EGLint v1[] = {EGL_CONTEXT_CLIENT_VERSION, 1, EGL_NONE};
  const EGLint v2[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
  EGLContext es1 = create(v1), es2 = create(v2);
  ASSERT_NE(es1, EGL_NO_CONTEXT);
  ASSERT_NE(es2, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, es1));
  EXPECT_EQ(gl_string(GL_VERSION), "OpenGL ES-CM 1.1 Pineda 0.1.0");
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, es2));
  EXPECT_EQ(gl_string(GL_VERSION), "OpenGL ES 2.0 Pineda 0.1.0");
}

// The ES 2.0 entry points are reachable through eglGetProcAddress as well as linked.
TEST_F(Es2Egl, ProcAddressesOfES2Functions) {
  for (const char* name : {"glCreateShader", "glGetShaderPrecisionFormat", "glReleaseShaderCompiler", "glShaderBinary",
                           "glMapBufferOES", "glUnmapBufferOES", "glGetBufferPointervOES", "glClearDepthf",
                           "glDepthRangef"})
    EXPECT_NE(eglGetProcAddress(name), nullptr) << name;
}

}  // namespace
}  // namespace pineda::es2_test
