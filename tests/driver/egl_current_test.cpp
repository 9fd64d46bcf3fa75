// eglMakeCurrent (pbuffers and surfaceless), current-object queries, rendering through GL,
// contexts used from several threads.
#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <thread>

#include "egl_fixture.h"

namespace {

using pineda_test::EglTest;
using EglCurrent = EglTest;

std::array<uint8_t, 4> pixel(int x, int y) {
  std::array<uint8_t, 4> p{1, 2, 3, 4};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p.data());
  return p;
}

TEST_F(EglCurrent, NothingIsCurrentInitially) {
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetCurrentDisplay(), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetCurrentSurface(EGL_READ), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetCurrentSurface(0x7777), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST_F(EglCurrent, PbufferBindingIsReported) {
  EGLConfig cfg = config();
  EGLSurface s = pbuffer(cfg, 16, 16);
  EGLContext ctx = context(cfg);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  EXPECT_EQ(eglGetCurrentContext(), ctx);
  EXPECT_EQ(eglGetCurrentDisplay(), dpy);
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), s);
  EXPECT_EQ(eglGetCurrentSurface(EGL_READ), s);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), EGL_NO_SURFACE);
}

TEST_F(EglCurrent, SurfacelessContext) {
  EGLContext ctx = context(config());
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(eglGetCurrentContext(), ctx);
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), EGL_NO_SURFACE);
  // GL works without a framebuffer.
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
}

TEST_F(EglCurrent, BadMatchCombinations) {
  EGLConfig cfg = config();
  EGLSurface s = pbuffer(cfg, 4, 4);
  EGLContext ctx = context(cfg);
  EXPECT_FALSE(eglMakeCurrent(dpy, s, s, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglMakeCurrent(dpy, s, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  EXPECT_FALSE(eglMakeCurrent(dpy, EGL_NO_SURFACE, s, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
  // A surface whose buffers differ from the context's config.
  EGLSurface shallow = pbuffer(config(16, 0), 4, 4);
  EXPECT_FALSE(eglMakeCurrent(dpy, shallow, shallow, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
}

TEST_F(EglCurrent, BadHandles) {
  EGLConfig cfg = config();
  EGLSurface s = pbuffer(cfg, 4, 4);
  EGLContext ctx = context(cfg);
  int junk = 0;
  EXPECT_FALSE(eglMakeCurrent(dpy, s, s, reinterpret_cast<EGLContext>(&junk)));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EGLSurface bad = reinterpret_cast<EGLSurface>(&junk);
  EXPECT_FALSE(eglMakeCurrent(dpy, bad, bad, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_FALSE(eglMakeCurrent(dpy, s, bad, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
}

TEST_F(EglCurrent, ContextCurrentElsewhereIsBadAccess) {
  EGLConfig cfg = config();
  EGLContext ctx = context(cfg);
  EGLSurface s = pbuffer(cfg, 4, 4);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  EGLBoolean ok_ctx = EGL_TRUE, ok_surface = EGL_TRUE;
  EGLint error_ctx = 0, error_surface = 0;
  std::thread([&] {
    eglBindAPI(EGL_OPENGL_API);
    ok_ctx = eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx);
    error_ctx = eglGetError();
    EGLContext mine = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, nullptr);
    ok_surface = eglMakeCurrent(dpy, s, s, mine);
    error_surface = eglGetError();
    eglDestroyContext(dpy, mine);
    eglReleaseThread();
  }).join();
  EXPECT_FALSE(ok_ctx);
  EXPECT_EQ(error_ctx, EGL_BAD_ACCESS);
  EXPECT_FALSE(ok_surface);
  EXPECT_EQ(error_surface, EGL_BAD_ACCESS);

  // Released here, it can be bound there.
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EGLBoolean ok = EGL_FALSE;
  std::thread([&] {
    eglBindAPI(EGL_OPENGL_API);
    ok = eglMakeCurrent(dpy, s, s, ctx);
    eglReleaseThread();
  }).join();
  EXPECT_TRUE(ok);
}

TEST_F(EglCurrent, ClearReachesThePbuffer) {
  EGLConfig cfg = config();
  EGLSurface s = pbuffer(cfg, 32, 16);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, context(cfg)));
  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(eglSwapBuffers(dpy, s));
  EXPECT_EQ(pixel(0, 0), (std::array<uint8_t, 4>{255, 0, 0, 255}));
  EXPECT_EQ(pixel(31, 15), (std::array<uint8_t, 4>{255, 0, 0, 255}));
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
}

TEST_F(EglCurrent, DestroyedWhileCurrentStaysUsableUntilReleased) {
  EGLConfig cfg = config();
  const EGLint size[] = {EGL_WIDTH, 8, EGL_HEIGHT, 8, EGL_NONE};
  EGLSurface s = eglCreatePbufferSurface(dpy, cfg, size);
  EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, nullptr);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  ASSERT_TRUE(eglDestroySurface(dpy, s));
  ASSERT_TRUE(eglDestroyContext(dpy, ctx));
  EXPECT_EQ(eglGetCurrentContext(), ctx);
  EXPECT_EQ(eglGetCurrentSurface(EGL_DRAW), s);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(pixel(7, 7), (std::array<uint8_t, 4>{0, 0, 255, 255}));
  // The handles are gone: rebinding them fails; releasing frees them.
  EXPECT_FALSE(eglMakeCurrent(dpy, s, s, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
}

TEST_F(EglCurrent, TwoThreadsRenderIndependently) {
  EGLConfig cfg = config();
  constexpr int kFrames = 20;
  auto worker = [&](float r, float g, float b, std::array<uint8_t, 4> expected, bool* ok) {
    eglBindAPI(EGL_OPENGL_API);
    const EGLint size[] = {EGL_WIDTH, 64, EGL_HEIGHT, 64, EGL_NONE};
    EGLSurface s = eglCreatePbufferSurface(dpy, cfg, size);
    EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, nullptr);
    *ok = eglMakeCurrent(dpy, s, s, ctx);
    for (int i = 0; i < kFrames && *ok; ++i) {
      glClearColor(r, g, b, 1);
      glClear(GL_COLOR_BUFFER_BIT);
      eglSwapBuffers(dpy, s);
      *ok = pixel(i, 63 - i) == expected;
    }
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroySurface(dpy, s);
    eglDestroyContext(dpy, ctx);
  };
  bool ok_a = false, ok_b = false;
  std::thread a(worker, 1.0f, 0.0f, 0.0f, std::array<uint8_t, 4>{255, 0, 0, 255}, &ok_a);
  std::thread b(worker, 0.0f, 1.0f, 0.0f, std::array<uint8_t, 4>{0, 255, 0, 255}, &ok_b);
  a.join();
  b.join();
  EXPECT_TRUE(ok_a);
  EXPECT_TRUE(ok_b);
}

TEST_F(EglCurrent, ReleaseThreadAndWait) {
  EGLContext ctx = context(config());
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_TRUE(eglWaitGL());
  EXPECT_TRUE(eglWaitClient());
  EXPECT_TRUE(eglWaitNative(EGL_CORE_NATIVE_ENGINE));
  EXPECT_FALSE(eglWaitNative(0x7777));
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_TRUE(eglReleaseThread());
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  EXPECT_TRUE(eglBindAPI(EGL_OPENGL_API));
}

}  // namespace

namespace {

using EglThreadExit = pineda_test::EglTest;

TEST_F(EglThreadExit, ThreadEndingWithAContextCurrentReleasesIt) {
  EGLContext ctx = context(config());
  EGLBoolean bound = EGL_FALSE;
  std::thread([&] {
    eglBindAPI(EGL_OPENGL_API);
    bound = eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx);
  }).join();
  ASSERT_TRUE(bound);
  EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
}

}  // namespace
