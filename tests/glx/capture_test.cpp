// PINEDA_CAPTURE=DIR writes every presented frame as DIR/frame-NNNNN.png. Runs in the ctest
// glx.CaptureUnderXvfb, which sets the variable to a fresh folder; skipped without it.
#include "glx_fixture.h"

#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <png.h>

#include <cstdlib>
#include <string>

namespace pineda_test {
namespace {

struct Png {
  int width = 0, height = 0;
  std::vector<uint8_t> rgb;
  // 0xRRGGBB at (x, y), y = 0 being the top row.
  uint32_t at(int x, int y) const {
    const uint8_t* p = &rgb[(static_cast<size_t>(y) * width + x) * 3];
    return (uint32_t(p[0]) << 16) | (uint32_t(p[1]) << 8) | p[2];
  }
};

bool read_png(const std::string& path, Png* out) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str())) return false;
  image.format = PNG_FORMAT_RGB;
  out->width = static_cast<int>(image.width);
  out->height = static_cast<int>(image.height);
  out->rgb.resize(PNG_IMAGE_SIZE(image));
  return png_image_finish_read(&image, nullptr, out->rgb.data(), 0, nullptr) != 0;
}

using GlxCaptureTest = GlxTest;

TEST_F(GlxCaptureTest, GlxSwapsAndEglPbufferSwapsAreNumberedPngs) {
  const char* dir = std::getenv("PINEDA_CAPTURE");
  if (!dir) GTEST_SKIP() << "PINEDA_CAPTURE is not set (ctest glx.CaptureUnderXvfb sets it)";
  const std::string folder = dir;

  GLXFBConfig config = rgba8(true, false);
  Window w = window(config, 16, 8);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, context(config)));
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 4, 2);  // bottom-left
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glXSwapBuffers(dpy, w);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glXSwapBuffers(dpy, w);
  ASSERT_TRUE(glXMakeCurrent(dpy, None, nullptr));

  EGLDisplay edpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  ASSERT_TRUE(eglInitialize(edpy, nullptr, nullptr));
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig c = nullptr;
  EGLint n = 0;
  ASSERT_TRUE(eglChooseConfig(edpy, attribs, &c, 1, &n));
  const EGLint size[] = {EGL_WIDTH, 5, EGL_HEIGHT, 3, EGL_NONE};
  EGLSurface s = eglCreatePbufferSurface(edpy, c, size);
  ASSERT_TRUE(eglMakeCurrent(edpy, s, s, eglCreateContext(edpy, c, EGL_NO_CONTEXT, nullptr)));
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 2, 1, 1);  // top-left
  glClearColor(1, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  ASSERT_TRUE(eglSwapBuffers(edpy, s));
  eglMakeCurrent(edpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglTerminate(edpy);

  Png first, second, third;
  ASSERT_TRUE(read_png(folder + "/frame-00000.png", &first));
  ASSERT_TRUE(read_png(folder + "/frame-00001.png", &second));
  ASSERT_TRUE(read_png(folder + "/frame-00002.png", &third));
  Png none;
  EXPECT_FALSE(read_png(folder + "/frame-00003.png", &none));
  EXPECT_EQ(first.width, 16);
  EXPECT_EQ(first.height, 8);
  EXPECT_EQ(first.at(0, 7), 0x0000ffu);  // PNG rows are top-down
  EXPECT_EQ(first.at(3, 6), 0x0000ffu);
  EXPECT_EQ(first.at(4, 7), 0xff0000u);
  EXPECT_EQ(first.at(0, 5), 0xff0000u);
  EXPECT_EQ(first.at(15, 0), 0xff0000u);
  EXPECT_EQ(second.at(0, 7), 0x00ff00u);
  EXPECT_EQ(third.width, 5);
  EXPECT_EQ(third.height, 3);
  EXPECT_EQ(third.at(0, 0), 0xffff00u);
  EXPECT_EQ(third.at(1, 0), 0x0000ffu);
  EXPECT_EQ(third.at(0, 2), 0x0000ffu);
}

}  // namespace
}  // namespace pineda_test
