// Front and back buffers of a double-buffered window: glDrawBuffer/glReadBuffer select them,
// glXSwapBuffers presents the back buffer and leaves it as it was (as llvmpipe does), front
// drawing reaches the window at glFlush, and ReadPixels reads alpha 1 without alpha bits.
#include "glx_fixture.h"

namespace pineda_test {
namespace {

using GlxFrontBackTest = GlxTest;

constexpr uint32_t kRed = 0xff0000, kGreen = 0x00ff00, kBlue = 0x0000ff, kGrey = 0x333333;

void clear_to(float r, float g, float b) {
  glClearColor(r, g, b, 1);
  glClear(GL_COLOR_BUFFER_BIT);
}

uint32_t read_from(GLenum buffer, int x, int y) {
  glReadBuffer(buffer);
  return gl_pixel(x, y);
}

// A 10x10 window-aligned quad at the bottom left, at normalized device depth `z` (window
// depth (z + 1) / 2), in `r, g, b`.
void corner_quad(float r, float g, float b, float z) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 20, 0, 20, -1, 1);
  glColor3f(r, g, b);
  glBegin(GL_QUADS);
  glVertex3f(0, 0, -z);
  glVertex3f(10, 0, -z);
  glVertex3f(10, 10, -z);
  glVertex3f(0, 10, -z);
  glEnd();
}

class FrontBack : public GlxFrontBackTest {
 protected:
  void make_current(bool depth_stencil) {
    GLXFBConfig config = rgba8(true, depth_stencil);
    ASSERT_NE(config, nullptr);
    w = window(config, 20, 20);
    ASSERT_TRUE(glXMakeCurrent(dpy, w, context(config)));
    glViewport(0, 0, 20, 20);
  }
  Window w = 0;
};

TEST_F(FrontBack, EachBufferKeepsItsOwnPixels) {
  make_current(false);
  glDrawBuffer(GL_FRONT);
  clear_to(1, 0, 0);
  glDrawBuffer(GL_BACK);
  clear_to(0, 1, 0);
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kRed);
  EXPECT_EQ(read_from(GL_FRONT_LEFT, 5, 5), kRed);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kGreen);
  EXPECT_EQ(read_from(GL_BACK_LEFT, 5, 5), kGreen);
  // Front drawing reached the window at the flush; the back buffer did not.
  glFlush();
  EXPECT_EQ(x_pixel(w, 5, 5), kRed);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(FrontBack, SwapPresentsTheBackAndKeepsIt) {
  make_current(false);
  glDrawBuffer(GL_FRONT);
  clear_to(1, 0, 0);
  glDrawBuffer(GL_BACK);
  clear_to(0, 0, 1);
  glXSwapBuffers(dpy, w);
  EXPECT_EQ(x_pixel(w, 19, 0), kBlue);
  EXPECT_EQ(read_from(GL_FRONT, 0, 19), kBlue);
  EXPECT_EQ(read_from(GL_BACK, 0, 19), kBlue);
  // Drawing the next frame does not touch the window until the next swap.
  glDrawBuffer(GL_BACK);
  clear_to(0, 1, 0);
  glFinish();
  EXPECT_EQ(x_pixel(w, 10, 10), kBlue);
  EXPECT_EQ(read_from(GL_FRONT, 10, 10), kBlue);
  glXSwapBuffers(dpy, w);
  EXPECT_EQ(x_pixel(w, 10, 10), kGreen);
}

TEST_F(FrontBack, FrontAndBackDrawsBothWithOneDepthTest) {
  make_current(true);
  glClearColor(0.2f, 0.2f, 0.2f, 1);
  glClearDepth(1);
  glDrawBuffer(GL_FRONT_AND_BACK);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  corner_quad(1, 0, 0, 0.5f);
  // Same depth: GL_LESS fails in both buffers, as it would for one buffer.
  corner_quad(0, 0, 1, 0.5f);
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kRed);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kRed);
  EXPECT_EQ(read_from(GL_FRONT, 15, 15), kGrey);
  EXPECT_EQ(read_from(GL_BACK, 15, 15), kGrey);
  float depth = 0;
  glReadPixels(5, 5, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  EXPECT_NEAR(depth, 0.75f, 1e-6f);
  // Nearer: drawn in both.
  corner_quad(0, 1, 0, 0.0f);
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kGreen);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kGreen);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(FrontBack, LeftIsFrontAndBack) {
  make_current(false);
  glDrawBuffer(GL_LEFT);
  clear_to(0, 0, 1);
  EXPECT_EQ(read_from(GL_FRONT_LEFT, 1, 1), kBlue);
  EXPECT_EQ(read_from(GL_BACK_LEFT, 1, 1), kBlue);
}

TEST_F(FrontBack, NoneDrawsNothing) {
  make_current(false);
  glDrawBuffer(GL_FRONT_AND_BACK);
  clear_to(1, 0, 0);
  glDrawBuffer(GL_NONE);
  clear_to(0, 1, 0);
  corner_quad(0, 0, 1, 0);
  EXPECT_EQ(read_from(GL_FRONT, 5, 5), kRed);
  EXPECT_EQ(read_from(GL_BACK, 5, 5), kRed);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(GlxFrontBackTest, ReadPixelsAlphaIsOneWithoutAlphaBits) {
  int n = 0;
  GLXFBConfig* configs = glXGetFBConfigs(dpy, screen, &n);
  GLXFBConfig config = nullptr;
  for (int i = 0; i < n && !config; ++i) {
    int alpha_size = -1, db = 0;
    glXGetFBConfigAttrib(dpy, configs[i], GLX_ALPHA_SIZE, &alpha_size);
    glXGetFBConfigAttrib(dpy, configs[i], GLX_DOUBLEBUFFER, &db);
    if (alpha_size == 0 && db) config = configs[i];
  }
  if (configs) XFree(configs);
  ASSERT_NE(config, nullptr);
  Window w = window(config, 8, 8);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, context(config)));
  GLint bits = -1;
  glGetIntegerv(GL_ALPHA_BITS, &bits);
  EXPECT_EQ(bits, 0);
  glClearColor(0.2f, 0.4f, 0.6f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  uint8_t rgba[4] = {};
  glReadPixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(rgba[0], 51);
  EXPECT_EQ(rgba[1], 102);
  EXPECT_EQ(rgba[2], 153);
  EXPECT_EQ(rgba[3], 255);
  // Whole rows (eight pixels at a time where the CPU has AVX2), in both byte orders.
  for (const GLenum format : {GL_RGBA, GL_BGRA}) {
    uint8_t row[8 * 4] = {};
    glReadPixels(0, 3, 8, 1, format, GL_UNSIGNED_BYTE, row);
    const uint8_t red = 51, blue = 153;
    const uint8_t want[4] = {format == GL_RGBA ? red : blue, 102, format == GL_RGBA ? blue : red, 255};
    for (int i = 0; i < 32; ++i) EXPECT_EQ(row[i], want[i % 4]) << std::hex << format << std::dec << " byte " << i;
  }
  // With alpha bits, the cleared alpha is read back.
  GLXFBConfig with_alpha = rgba8(true, false);
  Window w2 = window(with_alpha, 8, 8);
  ASSERT_TRUE(glXMakeCurrent(dpy, w2, context(with_alpha)));
  glClearColor(0.2f, 0.4f, 0.6f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glReadPixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(rgba[3], 0);
}

}  // namespace
}  // namespace pineda_test
