// A pbuffer of a 4x multisampled config renders per sample and reads resolved colour.
#include <GL/gl.h>

#include <utility>

#include "egl_fixture.h"

namespace {

using pineda_test::EglTest;
using EglMultisample = EglTest;

TEST_F(EglMultisample, PbufferResolvesOnRead) {
  const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                            EGL_SAMPLE_BUFFERS, 1, EGL_SAMPLES, 4, EGL_DEPTH_SIZE, 24, EGL_NONE};
  EGLConfig cfg = nullptr;
  EGLint n = 0;
  ASSERT_TRUE(eglChooseConfig(dpy, attribs, &cfg, 1, &n));
  ASSERT_EQ(n, 1);
  EGLSurface s = pbuffer(cfg, 16, 16);
  EGLContext ctx = context(cfg);
  ASSERT_TRUE(eglMakeCurrent(dpy, s, s, ctx));
  for (const auto& [pname, expected] : {std::pair{GL_SAMPLE_BUFFERS, 1}, std::pair{GL_SAMPLES, 4}}) {
    GLint v = -1;
    glGetIntegerv(pname, &v);
    EXPECT_EQ(v, expected) << pname;
  }
  glClear(GL_COLOR_BUFFER_BIT);  // to the default clear colour, (0, 0, 0, 0)
  glOrtho(0, 16, 0, 16, -1, 1);  // on the modelview matrix: the same window positions
  // A top edge at y = 4.7 covers samples 0, 1 and 2 (at y 0.125, 0.375, 0.625) of row 4.
  glColor4f(0, 1, 0, 1);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(16, 0);
  glVertex2f(16, 4.7f);
  glVertex2f(0, 0);
  glVertex2f(16, 4.7f);
  glVertex2f(0, 4.7f);
  glEnd();
  uint8_t p[4] = {1, 1, 1, 1};
  glReadPixels(8, 4, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(p[0], 0);
  EXPECT_EQ(p[1], 191);  // (3 * 255 + 2) / 4
  EXPECT_EQ(p[3], 191);
  glReadPixels(8, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(p[1], 255);
  EXPECT_TRUE(eglSwapBuffers(dpy, s));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
