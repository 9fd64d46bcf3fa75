// Pixmaps (glXCreatePixmap, glXCreateGLXPixmap) and pbuffers.
#include "glx_fixture.h"

namespace pineda_test {
namespace {

using GlxOffscreenTest = GlxTest;

Pixmap make_pixmap(Display* dpy, int screen, GLXFBConfig config, int width, int height) {
  XVisualInfo* vi = glXGetVisualFromFBConfig(dpy, config);
  Pixmap p = XCreatePixmap(dpy, RootWindow(dpy, screen), width, height, vi->depth);
  XFree(vi);
  return p;
}

TEST_F(GlxOffscreenTest, PixmapReceivesRenderingAtFinish) {
  GLXFBConfig config = choose({GLX_DRAWABLE_TYPE, GLX_PIXMAP_BIT, GLX_DOUBLEBUFFER, False});
  ASSERT_NE(config, nullptr);
  Pixmap pixmap = make_pixmap(dpy, screen, config, 30, 20);
  GLXPixmap gp = glXCreatePixmap(dpy, config, pixmap, nullptr);
  ASSERT_NE(gp, None);
  GLXContext ctx = context(config);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, gp, gp, ctx));
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 5, 5);
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFinish();
  EXPECT_EQ(gl_pixel(0, 0), 0xffff00u);
  EXPECT_EQ(x_pixel(pixmap, 0, 19), 0xffff00u);
  EXPECT_EQ(x_pixel(pixmap, 29, 0), 0x0000ffu);
  unsigned int width = 0;
  glXQueryDrawable(dpy, gp, GLX_WIDTH, &width);
  EXPECT_EQ(width, 30u);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, None, None, nullptr));
  glXDestroyPixmap(dpy, gp);
  XFreePixmap(dpy, pixmap);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxOffscreenTest, Glx12PixmapStartsWithThePixmapContents) {
  int attribs[] = {GLX_RGBA, GLX_RED_SIZE, 8, None};
  XVisualInfo* vi = glXChooseVisual(dpy, screen, attribs);
  ASSERT_NE(vi, nullptr);
  Pixmap pixmap = XCreatePixmap(dpy, RootWindow(dpy, screen), 16, 16, vi->depth);
  GC gc = XCreateGC(dpy, pixmap, 0, nullptr);
  XSetForeground(dpy, gc, 0x00ff00);
  XFillRectangle(dpy, pixmap, gc, 0, 0, 16, 16);
  XFreeGC(dpy, gc);
  GLXPixmap gp = glXCreateGLXPixmap(dpy, vi, pixmap);
  ASSERT_NE(gp, None);
  GLXContext ctx = glXCreateContext(dpy, vi, nullptr, True);
  contexts.push_back(ctx);
  XFree(vi);
  ASSERT_TRUE(glXMakeCurrent(dpy, gp, ctx));
  EXPECT_EQ(gl_pixel(8, 8), 0x00ff00u);
  uint8_t rgba[4] = {};
  glReadPixels(8, 8, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(rgba[3], 255) << "a 24-bit pixmap's pixels are opaque";
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  EXPECT_EQ(x_pixel(pixmap, 8, 8), 0xff0000u);
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));
  glXDestroyGLXPixmap(dpy, gp);
  XFreePixmap(dpy, pixmap);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxOffscreenTest, Pbuffer) {
  GLXFBConfig config = choose({GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT, GLX_DEPTH_SIZE, 24});
  ASSERT_NE(config, nullptr);
  const int attribs[] = {GLX_PBUFFER_WIDTH, 64, GLX_PBUFFER_HEIGHT, 32, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, config, attribs);
  ASSERT_NE(pb, None);
  unsigned int value = 0;
  glXQueryDrawable(dpy, pb, GLX_WIDTH, &value);
  EXPECT_EQ(value, 64u);
  glXQueryDrawable(dpy, pb, GLX_HEIGHT, &value);
  EXPECT_EQ(value, 32u);
  glXQueryDrawable(dpy, pb, GLX_PRESERVED_CONTENTS, &value);
  EXPECT_EQ(value, 1u);
  int id = 0;
  glXGetFBConfigAttrib(dpy, config, GLX_FBCONFIG_ID, &id);
  glXQueryDrawable(dpy, pb, GLX_FBCONFIG_ID, &value);
  EXPECT_EQ(static_cast<int>(value), id);

  GLXContext ctx = context(config);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, pb, pb, ctx));
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(viewport[2], 64);
  EXPECT_EQ(viewport[3], 32);
  glClearColor(0, 1, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(gl_pixel(63, 31), 0x00ffffu);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, None, None, nullptr));
  glXDestroyPbuffer(dpy, pb);
  EXPECT_TRUE(take_errors().empty());

  // A destroyed pbuffer is GLXBadDrawable.
  EXPECT_FALSE(glXMakeContextCurrent(dpy, pb, pb, ctx));
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadDrawable);
  glXDestroyPbuffer(dpy, pb);
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + GLXBadPbuffer);
}

TEST_F(GlxOffscreenTest, PbufferLimits) {
  GLXFBConfig config = choose({GLX_DRAWABLE_TYPE, GLX_PBUFFER_BIT});
  const int huge[] = {GLX_PBUFFER_WIDTH, 1 << 20, GLX_PBUFFER_HEIGHT, 4, None};
  EXPECT_EQ(glXCreatePbuffer(dpy, config, huge), None);
  auto errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadAlloc);
  const int largest[] = {GLX_PBUFFER_WIDTH, 1 << 20, GLX_PBUFFER_HEIGHT, 4, GLX_LARGEST_PBUFFER, True, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, config, largest);
  ASSERT_NE(pb, None);
  unsigned int width = 0;
  glXQueryDrawable(dpy, pb, GLX_WIDTH, &width);
  int max_width = 0;
  glXGetFBConfigAttrib(dpy, config, GLX_MAX_PBUFFER_WIDTH, &max_width);
  EXPECT_EQ(static_cast<int>(width), max_width);
  glXDestroyPbuffer(dpy, pb);
  EXPECT_TRUE(take_errors().empty());
}

// Draw to a window, read from a pbuffer (GLX 1.3 separate read drawable).
TEST_F(GlxOffscreenTest, SeparateReadDrawable) {
  GLXFBConfig config = rgba8(false, false);
  const int attribs[] = {GLX_PBUFFER_WIDTH, 8, GLX_PBUFFER_HEIGHT, 8, None};
  GLXPbuffer pb = glXCreatePbuffer(dpy, config, attribs);
  Window w = window(config, 8, 8);
  GLXContext ctx = context(config);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, pb, pb, ctx));
  glClearColor(1, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, w, pb, ctx));
  EXPECT_EQ(glXGetCurrentDrawable(), w);
  EXPECT_EQ(glXGetCurrentReadDrawable(), pb);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(gl_pixel(4, 4), 0xff00ffu);
  glFinish();
  EXPECT_EQ(x_pixel(w, 4, 4), 0x00ff00u);
  ASSERT_TRUE(glXMakeContextCurrent(dpy, None, None, nullptr));
  glXDestroyPbuffer(dpy, pb);
  EXPECT_TRUE(take_errors().empty());
}

}  // namespace
}  // namespace pineda_test
