// EGL with OpenGL ES 1.1: configs that carry EGL_OPENGL_ES_BIT, ES 1.x contexts through
// EGL_CONTEXT_CLIENT_VERSION and EGL_KHR_create_context, and the desktop GL context a program
// gets after choosing an ES config and binding EGL_OPENGL_API.
#include <GLES/gl.h>
#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

#include "tests/es1/egl_context.h"

namespace pineda::es1_test {
namespace {

constexpr EGLint kES1Renderable[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};

std::string gl_string(GLenum name) {
  const GLubyte* s = glGetString(name);
  return s ? reinterpret_cast<const char*>(s) : "<null>";
}

class EglEs1 : public ::testing::Test {
 protected:
  void SetUp() override {
    dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    ASSERT_NE(dpy, EGL_NO_DISPLAY);
    ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
  }
  void TearDown() override {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    for (EGLContext c : contexts) eglDestroyContext(dpy, c);
    eglBindAPI(EGL_OPENGL_API);
  }
  EGLint count(const EGLint* attribs) {
    EGLint n = -1;
    EXPECT_TRUE(eglChooseConfig(dpy, attribs, nullptr, 0, &n));
    return n;
  }
  EGLConfig first(const EGLint* attribs) {
    EGLConfig c = nullptr;
    EGLint n = 0;
    EXPECT_TRUE(eglChooseConfig(dpy, attribs, &c, 1, &n));
    EXPECT_EQ(n, 1);
    return c;
  }
  EGLContext create(EGLConfig config, const EGLint* attribs) {
    EGLContext c = eglCreateContext(dpy, config, EGL_NO_CONTEXT, attribs);
    if (c != EGL_NO_CONTEXT) contexts.push_back(c);
    return c;
  }
  EGLint context_value(EGLContext c, EGLint attribute) {
    EGLint v = -1;
    EXPECT_TRUE(eglQueryContext(dpy, c, attribute, &v));
    return v;
  }
  EGLDisplay dpy = EGL_NO_DISPLAY;
  std::vector<EGLContext> contexts;
};

TEST_F(EglEs1, ClientApisNameBoth) { EXPECT_STREQ(eglQueryString(dpy, EGL_CLIENT_APIS), "OpenGL OpenGL_ES"); }

TEST_F(EglEs1, EveryConfigRendersGLES1AndES2) {
  EGLint n = 0;
  ASSERT_TRUE(eglGetConfigs(dpy, nullptr, 0, &n));
  ASSERT_EQ(n, 9);
  std::vector<EGLConfig> configs(n);
  ASSERT_TRUE(eglGetConfigs(dpy, configs.data(), n, &n));
  for (EGLConfig c : configs) {
    EGLint renderable = 0, conformant = 0;
    EXPECT_TRUE(eglGetConfigAttrib(dpy, c, EGL_RENDERABLE_TYPE, &renderable));
    EXPECT_TRUE(eglGetConfigAttrib(dpy, c, EGL_CONFORMANT, &conformant));
    EXPECT_EQ(renderable, EGL_OPENGL_BIT | EGL_OPENGL_ES_BIT | EGL_OPENGL_ES2_BIT);
    EXPECT_EQ(conformant, EGL_OPENGL_BIT | EGL_OPENGL_ES_BIT);
  }
  const EGLint es[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  const EGLint both[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT | EGL_OPENGL_ES_BIT, EGL_SURFACE_TYPE,
                         EGL_PBUFFER_BIT, EGL_NONE};
  const EGLint es2[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  // The default EGL_RENDERABLE_TYPE is EGL_OPENGL_ES_BIT (EGL 1.5, table 3.4).
  const EGLint defaults[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_NONE};
  EXPECT_EQ(count(es), 9);
  EXPECT_EQ(count(both), 9);
  EXPECT_EQ(count(es2), 9);
  EXPECT_EQ(count(defaults), 9);
}

// What real programs do (issue 11): choose with EGL_OPENGL_ES_BIT, then ask for desktop GL 1.3.
TEST_F(EglEs1, ESConfigServesADesktopContext) {
  const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES_BIT, EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                            EGL_RED_SIZE, 8, EGL_NONE};
  EGLConfig config = first(attribs);
  ASSERT_NE(config, nullptr);
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  const EGLint gl13[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 3, EGL_NONE};
  EGLContext ctx = create(config, gl13);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  EXPECT_EQ(context_value(ctx, EGL_CONTEXT_CLIENT_TYPE), EGL_OPENGL_API);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(gl_string(GL_VERSION).rfind("2.1 Pineda", 0), 0u) << gl_string(GL_VERSION);
}

TEST_F(EglEs1, InitialApiIsES) {
  EGLenum api = 0;
  std::thread([&] { api = eglQueryAPI(); }).join();
  EXPECT_EQ(api, EGLenum(EGL_OPENGL_ES_API));
}

TEST_F(EglEs1, ClientVersion1GivesES11) {
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_ES_API));
  EGLConfig config = first(kES1Renderable);
  const EGLint v1[] = {EGL_CONTEXT_CLIENT_VERSION, 1, EGL_NONE};
  EGLContext ctx = create(config, v1);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  EXPECT_EQ(context_value(ctx, EGL_CONTEXT_CLIENT_TYPE), EGL_OPENGL_ES_API);
  EXPECT_EQ(context_value(ctx, EGL_CONTEXT_CLIENT_VERSION), 1);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(gl_string(GL_VERSION), "OpenGL ES-CM 1.1 Pineda 0.1.0");
  // No attributes: version 1 is the default.
  EXPECT_NE(create(config, nullptr), EGL_NO_CONTEXT);
}

TEST_F(EglEs1, CreateContextMajor1GivesES11) {
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_ES_API));
  EGLConfig config = first(kES1Renderable);
  for (EGLint minor : {0, 1}) {
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, minor, EGL_NONE};
    EGLContext ctx = create(config, attribs);
    ASSERT_NE(ctx, EGL_NO_CONTEXT) << minor;
    ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
    EXPECT_EQ(gl_string(GL_VERSION), "OpenGL ES-CM 1.1 Pineda 0.1.0") << minor;
  }
  const EGLint es12[] = {EGL_CONTEXT_MAJOR_VERSION, 1, EGL_CONTEXT_MINOR_VERSION, 2, EGL_NONE};
  EXPECT_EQ(create(config, es12), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
}

TEST_F(EglEs1, ES3IsNotOffered) {
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_ES_API));
  EGLConfig config = first(kES1Renderable);
  const EGLint v3[] = {EGL_CONTEXT_CLIENT_VERSION, 3, EGL_NONE};
  EXPECT_EQ(create(config, v3), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
}

TEST_F(EglEs1, DesktopOnlyAttributesAreErrorsForES) {
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_ES_API));
  EGLConfig config = first(kES1Renderable);
  const EGLint profile[] = {EGL_CONTEXT_CLIENT_VERSION, 1, EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
  EXPECT_EQ(create(config, profile), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
}

}  // namespace
}  // namespace pineda::es1_test
