// A window of a 4x multisampled config renders per sample and resolves on swap and
// glReadPixels (the configs themselves: glx_config_test.cpp).
#include "glx_fixture.h"

namespace pineda_test {
namespace {

using GlxMultisampleTest = GlxTest;

// A right edge at x = 4.5 covers samples 0 and 2 of column 4: half the red of the quad.
TEST_F(GlxMultisampleTest, WindowResolvesOnReadAndSwap) {
  GLXFBConfig config = choose({GLX_SAMPLE_BUFFERS, 1, GLX_SAMPLES, 4, GLX_DOUBLEBUFFER, True, GLX_DEPTH_SIZE, 24,
                               GLX_RENDER_TYPE, GLX_RGBA_BIT, None});
  ASSERT_NE(config, nullptr);
  Window w = window(config, 16, 16);
  GLXContext ctx = context(config);
  ASSERT_NE(ctx, nullptr);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, ctx));
  GLint v = -1;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &v);
  EXPECT_EQ(v, 1);
  glGetIntegerv(GL_SAMPLES, &v);
  EXPECT_EQ(v, 4);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 16, 0, 16, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glColor3f(1, 0, 0);
  glBegin(GL_QUADS);
  glVertex2f(0, 0);
  glVertex2f(4.5f, 0);
  glVertex2f(4.5f, 16);
  glVertex2f(0, 16);
  glEnd();
  EXPECT_EQ(gl_pixel(3, 8), 0xff0000u);
  EXPECT_EQ(gl_pixel(4, 8), 0x800000u);  // (2 * 255 + 2) / 4 = 128
  EXPECT_EQ(gl_pixel(5, 8), 0x000000u);
  glXSwapBuffers(dpy, w);
  EXPECT_EQ(x_pixel(w, 4, 8), 0x800000u);
  EXPECT_EQ(x_pixel(w, 3, 8), 0xff0000u);
  // The accumulation buffer loads the resolved colour and returns into every sample (were it
  // sample 0 only, column 3 would resolve to (127 + 3 * 255) / 4 = 223).
  glAccum(GL_LOAD, 0.5f);
  glAccum(GL_RETURN, 1.f);
  EXPECT_EQ(gl_pixel(4, 8), 0x400000u);
  EXPECT_EQ(gl_pixel(3, 8), 0x7f0000u);  // 255 / 2 through the accumulation buffer
  EXPECT_TRUE(take_errors().empty());
  glXMakeCurrent(dpy, None, nullptr);
}

}  // namespace
}  // namespace pineda_test
