// Rendering into windows: make current, clear, glReadPixels, glXSwapBuffers and what the X
// server shows, single buffering, GL_FRONT, resizes, two windows with two contexts.
#include "glx_fixture.h"

namespace pineda_test {
namespace {

using GlxWindowTest = GlxTest;

constexpr uint32_t kRed = 0xff0000, kGreen = 0x00ff00, kBlue = 0x0000ff;

TEST_F(GlxWindowTest, ClearReadPixelsAndSwap) {
  GLXFBConfig config = rgba8(true, true);
  ASSERT_NE(config, nullptr);
  Window w = window(config, 64, 48);
  GLXContext ctx = context(config);
  ASSERT_NE(ctx, nullptr);
  GLXWindow gw = glXCreateWindow(dpy, config, w, nullptr);
  ASSERT_NE(gw, None);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, gw, gw, ctx));
  EXPECT_EQ(glXGetCurrentContext(), ctx);
  EXPECT_EQ(glXGetCurrentDrawable(), gw);
  EXPECT_EQ(glXGetCurrentReadDrawable(), gw);
  EXPECT_EQ(glXGetCurrentDisplay(), dpy);

  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 64);
  EXPECT_EQ(viewport[3], 48);
  GLint bits = 0;
  glGetIntegerv(GL_DEPTH_BITS, &bits);
  EXPECT_EQ(bits, 24);
  glGetIntegerv(GL_STENCIL_BITS, &bits);
  EXPECT_EQ(bits, 8);
  GLboolean doublebuffer = GL_FALSE;
  glGetBooleanv(GL_DOUBLEBUFFER, &doublebuffer);
  EXPECT_TRUE(doublebuffer);

  clear_with_corner(0, 0, 1, 1, 0, 0);
  EXPECT_EQ(gl_pixel(0, 0), kRed);
  EXPECT_EQ(gl_pixel(9, 9), kRed);
  EXPECT_EQ(gl_pixel(10, 10), kBlue);
  EXPECT_EQ(gl_pixel(63, 47), kBlue);

  glXSwapBuffers(dpy, gw);
  // GL's row 0 is the bottom row of the window.
  EXPECT_EQ(x_pixel(w, 0, 47), kRed);
  EXPECT_EQ(x_pixel(w, 9, 38), kRed);
  EXPECT_EQ(x_pixel(w, 0, 0), kBlue);
  EXPECT_EQ(x_pixel(w, 63, 47), kBlue);
  EXPECT_TRUE(take_errors().empty());

  ASSERT_TRUE(glXMakeContextCurrent(dpy, None, None, nullptr));
  EXPECT_EQ(glXGetCurrentContext(), nullptr);
  EXPECT_EQ(glXGetCurrentDrawable(), None);
  glXDestroyWindow(dpy, gw);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxWindowTest, PlainWindowWithGlx12Calls) {
  int attribs[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, None};
  XVisualInfo* vi = glXChooseVisual(dpy, screen, attribs);
  ASSERT_NE(vi, nullptr);
  GLXContext ctx = glXCreateContext(dpy, vi, nullptr, True);
  ASSERT_NE(ctx, nullptr);
  contexts.push_back(ctx);
  EXPECT_TRUE(glXIsDirect(dpy, ctx));
  Window root = RootWindow(dpy, screen);
  XSetWindowAttributes wa{};
  wa.colormap = XCreateColormap(dpy, root, vi->visual, AllocNone);
  Window w = XCreateWindow(dpy, root, 0, 0, 32, 32, 0, vi->depth, InputOutput, vi->visual,
                           CWColormap, &wa);
  XFree(vi);
  windows.push_back(w);
  XMapWindow(dpy, w);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(gl_pixel(31, 31), kGreen);
  glXSwapBuffers(dpy, w);
  EXPECT_EQ(x_pixel(w, 16, 16), kGreen);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxWindowTest, SingleBufferedShowsAtFlush) {
  GLXFBConfig config = rgba8(false, false);
  ASSERT_NE(config, nullptr);
  Window w = window(config, 20, 20);
  GLXContext ctx = context(config);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  GLint buffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &buffer);
  EXPECT_EQ(buffer, GL_FRONT);
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  EXPECT_EQ(x_pixel(w, 5, 5), kRed);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_EQ(x_pixel(w, 5, 5), kBlue);
}

TEST_F(GlxWindowTest, FrontBufferDrawingOnDoubleBufferedWindow) {
  GLXFBConfig config = rgba8(true, false);
  Window w = window(config, 20, 20);
  GLXContext ctx = context(config);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  glDrawBuffer(GL_FRONT);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  EXPECT_EQ(x_pixel(w, 3, 3), kGreen);
  glDrawBuffer(GL_BACK);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlxWindowTest, ResizedWindowRendersAtTheNewSize) {
  GLXFBConfig config = rgba8(true, true);
  Window w = window(config, 40, 30);
  GLXContext ctx = context(config);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy, w);

  XResizeWindow(dpy, w, 120, 90);
  XSync(dpy, False);
  // The swap notices the new size: the next frame renders at it.
  glXSwapBuffers(dpy, w);
  unsigned int width = 0, height = 0;
  glXQueryDrawable(dpy, w, GLX_WIDTH, &width);
  glXQueryDrawable(dpy, w, GLX_HEIGHT, &height);
  EXPECT_EQ(width, 120u);
  EXPECT_EQ(height, 90u);
  glViewport(0, 0, 120, 90);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(gl_pixel(119, 89), kGreen);
  glXSwapBuffers(dpy, w);
  EXPECT_EQ(x_pixel(w, 119, 0), kGreen);
  EXPECT_EQ(x_pixel(w, 0, 89), kGreen);

  // Resizing between make-currents works too.
  XResizeWindow(dpy, w, 50, 60);
  XSync(dpy, False);
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  glViewport(0, 0, 50, 60);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(gl_pixel(49, 59), kBlue);
  glXSwapBuffers(dpy, w);
  EXPECT_EQ(x_pixel(w, 49, 59), kBlue);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxWindowTest, TwoWindowsTwoContexts) {
  GLXFBConfig config = rgba8(true, true);
  Window a = window(config, 30, 30), b = window(config, 50, 20);
  GLXContext ca = context(config), cb = context(config);
  ASSERT_TRUE(glXMakeCurrent(dpy, a, ca));
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(glXMakeCurrent(dpy, b, cb));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy, b);
  ASSERT_TRUE(glXMakeCurrent(dpy, a, ca));
  // Each context kept its own state; each window its own buffer.
  EXPECT_EQ(gl_pixel(29, 29), kRed);
  GLfloat clear[4] = {};
  glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
  EXPECT_EQ(clear[0], 1.0f);
  glXSwapBuffers(dpy, a);
  EXPECT_EQ(x_pixel(a, 15, 15), kRed);
  EXPECT_EQ(x_pixel(b, 45, 15), kGreen);
  // One context on the other window.
  ASSERT_TRUE(glXMakeCurrent(dpy, b, ca));
  EXPECT_EQ(gl_pixel(49, 19), kGreen);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxWindowTest, FrontBufferAfterSwapHoldsTheFrame) {
  GLXFBConfig config = rgba8(true, false);
  Window w = window(config, 16, 16);
  GLXContext ctx = context(config);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  glDrawBuffer(GL_BACK);
  glClearColor(0, 1, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy, w);
  glReadBuffer(GL_FRONT);
  float rgba[4] = {};
  glReadPixels(8, 8, 1, 1, GL_RGBA, GL_FLOAT, rgba);
  EXPECT_EQ(rgba[0], 0.0f);
  EXPECT_EQ(rgba[1], 1.0f);
  EXPECT_EQ(rgba[2], 0.0f);
  EXPECT_EQ(x_pixel(w, 8, 8), kGreen);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlxWindowTest, SwapInterval) {
  GLXFBConfig config = rgba8(true, false);
  Window w = window(config, 8, 8);
  GLXContext ctx = context(config);
  GLXWindow gw = glXCreateWindow(dpy, config, w, nullptr);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, gw, gw, ctx));
  unsigned int value = 0;
  glXQueryDrawable(dpy, gw, GLX_SWAP_INTERVAL_EXT, &value);
  EXPECT_EQ(value, 1u);
  glXSwapIntervalEXT(dpy, gw, 0);
  glXQueryDrawable(dpy, gw, GLX_SWAP_INTERVAL_EXT, &value);
  EXPECT_EQ(value, 0u);
  EXPECT_EQ(glXSwapIntervalMESA(3), 0);
  EXPECT_EQ(glXGetSwapIntervalMESA(), 3);
  EXPECT_EQ(glXSwapIntervalSGI(2), 0);
  EXPECT_EQ(glXGetSwapIntervalMESA(), 2);
  EXPECT_EQ(glXSwapIntervalSGI(0), GLX_BAD_VALUE);
  glXQueryDrawable(dpy, gw, GLX_MAX_SWAP_INTERVAL_EXT, &value);
  EXPECT_GE(value, 1u);
  EXPECT_TRUE(take_errors().empty());
  glXSwapIntervalEXT(dpy, gw, -1);
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadValue);
  glXMakeContextCurrent(dpy, None, None, nullptr);
  glXDestroyWindow(dpy, gw);
}

}  // namespace
}  // namespace pineda_test
