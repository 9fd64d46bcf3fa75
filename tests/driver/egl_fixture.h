// A test fixture with an initialized surfaceless display and the OpenGL API bound.
#pragma once
#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

namespace pineda_test {

class EglTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    ASSERT_NE(dpy, EGL_NO_DISPLAY);
    ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
    ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  }
  void TearDown() override {
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    for (EGLSurface s : surfaces) eglDestroySurface(dpy, s);
    for (EGLContext c : contexts) eglDestroyContext(dpy, c);
    eglGetError();
  }

  // The config with these depth/stencil sizes and RGBA8888.
  EGLConfig config(EGLint depth = 24, EGLint stencil = 8) {
    const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                              EGL_OPENGL_BIT, EGL_DEPTH_SIZE, depth, EGL_STENCIL_SIZE, stencil,
                              EGL_NONE};
    EGLConfig configs[16];
    EGLint n = 0;
    EXPECT_TRUE(eglChooseConfig(dpy, attribs, configs, 16, &n));
    for (EGLint i = 0; i < n; ++i) {
      EGLint d = -1, s = -1;
      eglGetConfigAttrib(dpy, configs[i], EGL_DEPTH_SIZE, &d);
      eglGetConfigAttrib(dpy, configs[i], EGL_STENCIL_SIZE, &s);
      if (d == depth && s == stencil) return configs[i];
    }
    ADD_FAILURE() << "no config with depth " << depth << " stencil " << stencil;
    return nullptr;
  }

  EGLContext context(EGLConfig cfg, const EGLint* attribs = nullptr) {
    EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, attribs);
    if (ctx != EGL_NO_CONTEXT) contexts.push_back(ctx);
    return ctx;
  }

  EGLSurface pbuffer(EGLConfig cfg, EGLint width, EGLint height) {
    const EGLint attribs[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
    EGLSurface s = eglCreatePbufferSurface(dpy, cfg, attribs);
    if (s != EGL_NO_SURFACE) surfaces.push_back(s);
    return s;
  }

  // Whether the configs offer OpenGL ES 2.0: the ES 2.0 tests run only then. (ES 1.1 is
  // always offered: tests/es1/.)
  bool offers_gles2() {
    EGLConfig c = nullptr;
    EGLint n = 0, renderable = 0;
    if (!eglGetConfigs(dpy, &c, 1, &n) || n < 1) return false;
    eglGetConfigAttrib(dpy, c, EGL_RENDERABLE_TYPE, &renderable);
    return (renderable & EGL_OPENGL_ES2_BIT) != 0;
  }

  EGLDisplay dpy = EGL_NO_DISPLAY;
  std::vector<EGLContext> contexts;
  std::vector<EGLSurface> surfaces;
};

}  // namespace pineda_test
