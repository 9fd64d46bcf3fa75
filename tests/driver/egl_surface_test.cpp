// Pbuffer surfaces: creation, attributes, destruction, swap.
#include <GL/gl.h>

#include "egl_fixture.h"

namespace {

using pineda_test::EglTest;
using EglSurface = EglTest;

EGLint query(EGLDisplay dpy, EGLSurface s, EGLint attribute) {
  EGLint value = -12345;
  EXPECT_TRUE(eglQuerySurface(dpy, s, attribute, &value)) << std::hex << attribute;
  return value;
}

TEST_F(EglSurface, PbufferHasItsSize) {
  EGLConfig cfg = config();
  EGLSurface s = pbuffer(cfg, 160, 90);
  ASSERT_NE(s, EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  EXPECT_EQ(query(dpy, s, EGL_WIDTH), 160);
  EXPECT_EQ(query(dpy, s, EGL_HEIGHT), 90);
  EGLint id = 0;
  eglGetConfigAttrib(dpy, cfg, EGL_CONFIG_ID, &id);
  EXPECT_EQ(query(dpy, s, EGL_CONFIG_ID), id);
  EXPECT_EQ(query(dpy, s, EGL_LARGEST_PBUFFER), EGL_FALSE);
  EXPECT_EQ(query(dpy, s, EGL_RENDER_BUFFER), EGL_BACK_BUFFER);
  EXPECT_EQ(query(dpy, s, EGL_TEXTURE_FORMAT), EGL_NO_TEXTURE);
  EGLint value;
  EXPECT_FALSE(eglQuerySurface(dpy, s, 0x7777, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
}

TEST_F(EglSurface, DefaultSizeIsZero) {
  EGLSurface s = eglCreatePbufferSurface(dpy, config(), nullptr);
  ASSERT_NE(s, EGL_NO_SURFACE);
  surfaces.push_back(s);
  EXPECT_EQ(query(dpy, s, EGL_WIDTH), 0);
  EXPECT_EQ(query(dpy, s, EGL_HEIGHT), 0);
  // Rendering into it is harmless.
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, context(config())));
  glClearColor(1, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  EXPECT_TRUE(eglSwapBuffers(dpy, s));
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
}

TEST_F(EglSurface, NegativeSizeIsBadParameter) {
  EXPECT_EQ(pbuffer(config(), -1, 4), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST_F(EglSurface, TooLargeIsBadAllocUnlessLargestPbuffer) {
  EGLConfig cfg = config();
  EXPECT_EQ(pbuffer(cfg, 100000, 4), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ALLOC);
  const EGLint attribs[] = {EGL_WIDTH, 100000, EGL_HEIGHT, 2, EGL_LARGEST_PBUFFER, EGL_TRUE,
                            EGL_NONE};
  EGLSurface s = eglCreatePbufferSurface(dpy, cfg, attribs);
  ASSERT_NE(s, EGL_NO_SURFACE);
  surfaces.push_back(s);
  EXPECT_EQ(query(dpy, s, EGL_WIDTH), 8192);
  EXPECT_EQ(query(dpy, s, EGL_HEIGHT), 2);
  EXPECT_EQ(query(dpy, s, EGL_LARGEST_PBUFFER), EGL_TRUE);
}

TEST_F(EglSurface, BadAttributeConfigAndMatch) {
  const EGLint unknown[] = {0x7777, 1, EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(dpy, config(), unknown), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
  EXPECT_EQ(eglCreatePbufferSurface(dpy, nullptr, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_CONFIG);
  const EGLint texture[] = {EGL_TEXTURE_FORMAT, EGL_TEXTURE_RGBA, EGL_TEXTURE_TARGET,
                            EGL_TEXTURE_2D, EGL_NONE};
  EXPECT_EQ(eglCreatePbufferSurface(dpy, config(), texture), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_MATCH);
}

TEST_F(EglSurface, DestroyTwiceIsBadSurface) {
  EGLSurface s = eglCreatePbufferSurface(dpy, config(), nullptr);
  ASSERT_NE(s, EGL_NO_SURFACE);
  EXPECT_TRUE(eglDestroySurface(dpy, s));
  EXPECT_FALSE(eglDestroySurface(dpy, s));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EGLint value;
  EXPECT_FALSE(eglQuerySurface(dpy, s, EGL_WIDTH, &value));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
}

TEST_F(EglSurface, SwapBuffersNeedsTheCurrentSurface) {
  EGLConfig cfg = config();
  EGLSurface s = pbuffer(cfg, 8, 8), other = pbuffer(cfg, 8, 8);
  EXPECT_FALSE(eglSwapBuffers(dpy, s));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EGLContext ctx = context(cfg);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  EXPECT_TRUE(eglSwapBuffers(dpy, s));
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  EXPECT_FALSE(eglSwapBuffers(dpy, other));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_FALSE(eglSwapBuffers(dpy, EGL_NO_SURFACE));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
  EXPECT_TRUE(eglSwapInterval(dpy, 0));
  EXPECT_TRUE(eglSwapInterval(dpy, 5));  // clamped to the maximum
}

TEST_F(EglSurface, SwapIntervalNeedsAContextAndSurface) {
  EXPECT_FALSE(eglSwapInterval(dpy, 1));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EGLContext ctx = context(config());
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));
  EXPECT_FALSE(eglSwapInterval(dpy, 1));
  EXPECT_EQ(eglGetError(), EGL_BAD_SURFACE);
}

}  // namespace
