// A test fixture with an open X display (the tests run under Xvfb), an X error recorder,
// and helpers for windows, configs and reading back what reached the server.
#pragma once
// GoogleTest before Xlib: X.h defines macros (None, Bool...) that GoogleTest's names use.
#include <gtest/gtest.h>

#define GLX_GLXEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>

#include <cstdint>
#include <vector>

namespace pineda_test {

// GLX error codes, offsets from the extension's error base (GL/glxproto.h's values).
constexpr int GLXBadContext = 0, GLXBadDrawable = 2, GLXBadPixmap = 3, GLXBadFBConfig = 9,
              GLXBadPbuffer = 10, GLXBadWindow = 12, GLXBadProfileARB = 13;

// The X errors raised since the last take_errors(); the handler is process-wide.
std::vector<XErrorEvent>& recorded_errors();
int record_error(Display*, XErrorEvent* e);

class GlxTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

  // The first config matching `attribs` (None-terminated), or nullptr.
  GLXFBConfig choose(std::vector<int> attribs);
  GLXFBConfig rgba8(bool double_buffered, bool depth_stencil);
  Window window(GLXFBConfig config, int width, int height);
  GLXContext context(GLXFBConfig config);
  // The pixel at X coordinates (x, y) of a window or pixmap, as 0xRRGGBB.
  uint32_t x_pixel(Drawable d, int x, int y);
  // Synchronises and returns the X errors seen so far, clearing the record.
  std::vector<XErrorEvent> take_errors();
  int glx_error_base() const { return error_base_; }

  Display* dpy = nullptr;
  int screen = 0;
  std::vector<Window> windows;
  std::vector<GLXContext> contexts;

 private:
  int error_base_ = 0;
  XErrorHandler previous_ = nullptr;
};

// glReadPixels of one pixel as 0xRRGGBB.
uint32_t gl_pixel(int x, int y);

// Clears everything to `background` and the bottom-left 10x10 pixels to `corner`.
void clear_with_corner(float br, float bg, float bb, float cr, float cg, float cb);

}  // namespace pineda_test
