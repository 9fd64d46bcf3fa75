// glXUseXFont: the display lists draw exactly the pixels the X server draws for the same
// string, and advance the raster position by the glyphs' widths; errors for a bad font and
// for a call while a display list is being compiled.
#include "glx_fixture.h"

#include <cstring>

namespace pineda_test {
namespace {

using GlxUseXFontTest = GlxTest;

constexpr int kWidth = 64, kHeight = 32;

// The window's pixels (or a pixmap's) as 0xRRGGBB, top row first.
std::vector<uint32_t> x_pixels(Display* dpy, Drawable d) {
  std::vector<uint32_t> out;
  XImage* image = XGetImage(dpy, d, 0, 0, kWidth, kHeight, AllPlanes, ZPixmap);
  if (!image) return out;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) out.push_back(static_cast<uint32_t>(XGetPixel(image, x, y)) & 0xffffff);
  XDestroyImage(image);
  return out;
}

TEST_F(GlxUseXFontTest, ListsDrawWhatTheServerDraws) {
  XFontStruct* font = XLoadQueryFont(dpy, "fixed");
  ASSERT_NE(font, nullptr) << "the X server has no 'fixed' font";
  GLXFBConfig config = rgba8(true, false);
  Window w = window(config, kWidth, kHeight);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, context(config)));
  glViewport(0, 0, kWidth, kHeight);
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, kWidth, 0, kHeight, -1, 1);
  glClearColor(0, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);

  const GLuint base = glGenLists(96);
  glXUseXFont(font->fid, 32, 96, static_cast<int>(base));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  EXPECT_TRUE(glIsList(base + ('A' - 32)));
  glColor3f(1, 1, 1);
  glRasterPos2i(10, 10);
  glListBase(base - 32);
  const char* text = "Ag|";
  glCallLists(3, GL_UNSIGNED_BYTE, text);
  float position[4] = {};
  glGetFloatv(GL_CURRENT_RASTER_POSITION, position);
  EXPECT_EQ(position[0], 10.0f + XTextWidth(font, text, 3));
  EXPECT_EQ(position[1], 10.0f);
  glXSwapBuffers(dpy, w);

  // The server draws the same string with its baseline on the same row: GL's window row 10
  // is X's row kHeight - 1 - 10, the baseline's row is the one below the glyphs' bottom.
  Pixmap reference = XCreatePixmap(dpy, w, kWidth, kHeight, 24);
  GC gc = XCreateGC(dpy, reference, 0, nullptr);
  XSetForeground(dpy, gc, 0);
  XFillRectangle(dpy, reference, gc, 0, 0, kWidth, kHeight);
  XSetForeground(dpy, gc, 0xffffff);
  XSetFont(dpy, gc, font->fid);
  XDrawString(dpy, reference, gc, 10, kHeight - 10, text, 3);
  const std::vector<uint32_t> expected = x_pixels(dpy, reference), got = x_pixels(dpy, w);
  ASSERT_EQ(got.size(), expected.size());
  int white = 0, differing = 0;
  for (size_t i = 0; i < got.size(); ++i) {
    white += expected[i] == 0xffffff;
    differing += got[i] != expected[i];
  }
  EXPECT_GT(white, 20);
  EXPECT_EQ(differing, 0);
  XFreeGC(dpy, gc);
  XFreePixmap(dpy, reference);
  XFreeFont(dpy, font);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(GlxUseXFontTest, BadFontAndListCompilationAreErrors) {
  GLXFBConfig config = rgba8(true, false);
  Window w = window(config, 8, 8);
  ASSERT_TRUE(glXMakeCurrent(dpy, w, context(config)));
  glXUseXFont(0x1fffffff, 32, 10, 1);
  std::vector<XErrorEvent> errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, BadFont);
  EXPECT_FALSE(glIsList(1));

  Font font = XLoadFont(dpy, "fixed");
  glNewList(7, GL_COMPILE);
  glXUseXFont(font, 32, 10, 1);
  glEndList();
  errors = take_errors();
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_EQ(errors[0].error_code, glx_error_base() + 1);  // GLXBadContextState
  EXPECT_FALSE(glIsList(1));
  XUnloadFont(dpy, font);
}

}  // namespace
}  // namespace pineda_test
