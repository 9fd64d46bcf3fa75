#include "glx_fixture.h"

namespace pineda_test {

std::vector<XErrorEvent>& recorded_errors() {
  static std::vector<XErrorEvent> errors;
  return errors;
}

int record_error(Display*, XErrorEvent* e) {
  recorded_errors().push_back(*e);
  return 0;
}

void GlxTest::SetUp() {
  // An X server resets when its last client leaves, and refuses connections meanwhile: one
  // connection stays open for the whole run.
  static Display* keeper = XOpenDisplay(nullptr);
  ASSERT_NE(keeper, nullptr) << "no X display: run under xvfb-run";
  dpy = XOpenDisplay(nullptr);
  ASSERT_NE(dpy, nullptr) << "no X display: run under xvfb-run";
  screen = DefaultScreen(dpy);
  previous_ = XSetErrorHandler(record_error);
  recorded_errors().clear();
  int event_base = 0;
  ASSERT_TRUE(glXQueryExtension(dpy, &error_base_, &event_base));
}

void GlxTest::TearDown() {
  if (!dpy) return;
  glXMakeCurrent(dpy, None, nullptr);
  for (GLXContext c : contexts) glXDestroyContext(dpy, c);
  for (Window w : windows) XDestroyWindow(dpy, w);
  XSync(dpy, False);
  XSetErrorHandler(previous_);
  XCloseDisplay(dpy);
}

GLXFBConfig GlxTest::choose(std::vector<int> attribs) {
  attribs.push_back(None);
  int n = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy, screen, attribs.data(), &n);
  GLXFBConfig result = n > 0 ? configs[0] : nullptr;
  if (configs) XFree(configs);
  return result;
}

GLXFBConfig GlxTest::rgba8(bool double_buffered, bool depth_stencil) {
  int n = 0;
  GLXFBConfig* configs = glXGetFBConfigs(dpy, screen, &n);
  GLXFBConfig result = nullptr;
  for (int i = 0; i < n && !result; ++i) {
    int db = 0, depth = 0, stencil = 0, alpha = 0;
    glXGetFBConfigAttrib(dpy, configs[i], GLX_DOUBLEBUFFER, &db);
    glXGetFBConfigAttrib(dpy, configs[i], GLX_DEPTH_SIZE, &depth);
    glXGetFBConfigAttrib(dpy, configs[i], GLX_STENCIL_SIZE, &stencil);
    glXGetFBConfigAttrib(dpy, configs[i], GLX_ALPHA_SIZE, &alpha);
    if (db == double_buffered && (depth == 24 && stencil == 8) == depth_stencil &&
        (depth == 0) == !depth_stencil && alpha == 8)
      result = configs[i];
  }
  if (configs) XFree(configs);
  return result;
}

Window GlxTest::window(GLXFBConfig config, int width, int height) {
  XVisualInfo* vi = glXGetVisualFromFBConfig(dpy, config);
  if (!vi) return None;
  Window root = RootWindow(dpy, screen);
  XSetWindowAttributes attributes{};
  attributes.colormap = XCreateColormap(dpy, root, vi->visual, AllocNone);
  attributes.border_pixel = 0;
  // Side by side: XGetImage of a window shows what overlaps it.
  const int x = 200 * static_cast<int>(windows.size());
  Window w = XCreateWindow(dpy, root, x, 0, width, height, 0, vi->depth, InputOutput, vi->visual,
                           CWColormap | CWBorderPixel, &attributes);
  XFree(vi);
  XMapWindow(dpy, w);
  XSync(dpy, False);
  windows.push_back(w);
  return w;
}

GLXContext GlxTest::context(GLXFBConfig config) {
  GLXContext c = glXCreateNewContext(dpy, config, GLX_RGBA_TYPE, nullptr, True);
  if (c) contexts.push_back(c);
  return c;
}

uint32_t GlxTest::x_pixel(Drawable d, int x, int y) {
  XImage* image = XGetImage(dpy, d, x, y, 1, 1, AllPlanes, ZPixmap);
  if (!image) return 0xdeadbeef;
  uint32_t pixel = static_cast<uint32_t>(XGetPixel(image, 0, 0)) & 0xffffff;
  XDestroyImage(image);
  return pixel;
}

std::vector<XErrorEvent> GlxTest::take_errors() {
  XSync(dpy, False);
  std::vector<XErrorEvent> errors = std::move(recorded_errors());
  recorded_errors().clear();
  return errors;
}

uint32_t gl_pixel(int x, int y) {
  uint8_t rgba[4] = {};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  return (uint32_t(rgba[0]) << 16) | (uint32_t(rgba[1]) << 8) | rgba[2];
}

void clear_with_corner(float br, float bg, float bb, float cr, float cg, float cb) {
  glClearColor(br, bg, bb, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 10, 10);
  glClearColor(cr, cg, cb, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace pineda_test
