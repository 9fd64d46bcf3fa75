// EGL on the X11 platform: displays from an Xlib Display*, configs with native visuals,
// window and pixmap surfaces, swaps that reach the X server, resizes, destroyed windows.
#include "glx_fixture.h"

#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>
#include <string>

namespace pineda_test {
namespace {

constexpr uint32_t kRed = 0xff0000, kGreen = 0x00ff00, kBlue = 0x0000ff;

class EglX11Test : public GlxTest {
 protected:
  void SetUp() override {
    GlxTest::SetUp();
    if (HasFatalFailure()) return;
    edpy = eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, dpy, nullptr);
    ASSERT_NE(edpy, EGL_NO_DISPLAY);
    ASSERT_TRUE(eglInitialize(edpy, nullptr, nullptr));
    ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  }
  void TearDown() override {
    if (edpy != EGL_NO_DISPLAY) {
      eglMakeCurrent(edpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      eglTerminate(edpy);
    }
    GlxTest::TearDown();
  }

  EGLConfig window_config() {
    const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT | EGL_PIXMAP_BIT, EGL_RED_SIZE, 8,
                              EGL_DEPTH_SIZE, 24, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig c = nullptr;
    EGLint n = 0;
    if (!eglChooseConfig(edpy, attribs, &c, 1, &n) || n < 1) return nullptr;
    return c;
  }
  // A mapped window of the config's native visual.
  Window native_window(EGLConfig c, int width, int height) {
    EGLint visual_id = 0;
    eglGetConfigAttrib(edpy, c, EGL_NATIVE_VISUAL_ID, &visual_id);
    XVisualInfo tmpl{};
    tmpl.visualid = static_cast<VisualID>(visual_id);
    int n = 0;
    XVisualInfo* vi = XGetVisualInfo(dpy, VisualIDMask, &tmpl, &n);
    if (!vi) return None;
    Window root = RootWindow(dpy, screen);
    XSetWindowAttributes attributes{};
    attributes.colormap = XCreateColormap(dpy, root, vi->visual, AllocNone);
    Window w = XCreateWindow(dpy, root, 200 * static_cast<int>(windows.size()), 0, width, height, 0,
                             vi->depth, InputOutput, vi->visual, CWColormap, &attributes);
    XFree(vi);
    XMapWindow(dpy, w);
    XSync(dpy, False);
    windows.push_back(w);
    return w;
  }
  EGLContext egl_context(EGLConfig c) { return eglCreateContext(edpy, c, EGL_NO_CONTEXT, nullptr); }

  EGLDisplay edpy = EGL_NO_DISPLAY;
};

bool has_extension(const char* list, const std::string& name) {
  const std::string padded = " " + std::string(list ? list : "") + " ";
  return padded.find(" " + name + " ") != std::string::npos;
}

TEST_F(EglX11Test, GetDisplayTakesAnXlibDisplay) {
  EXPECT_EQ(eglGetDisplay(reinterpret_cast<EGLNativeDisplayType>(dpy)), edpy);
  EXPECT_EQ(eglGetPlatformDisplayEXT(EGL_PLATFORM_X11_EXT, dpy, nullptr), edpy);
  EXPECT_NE(eglGetDisplay(EGL_DEFAULT_DISPLAY), edpy);
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  for (const char* name : {"EGL_EXT_platform_base", "EGL_KHR_platform_x11", "EGL_EXT_platform_x11",
                           "EGL_MESA_platform_surfaceless", "EGL_EXT_client_extensions"})
    EXPECT_TRUE(has_extension(client, name)) << name;
  // EGL_DEFAULT_DISPLAY on the X11 platform opens the default X display.
  EGLDisplay own = eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, EGL_DEFAULT_DISPLAY, nullptr);
  ASSERT_NE(own, EGL_NO_DISPLAY);
  EXPECT_TRUE(eglInitialize(own, nullptr, nullptr));
  EXPECT_TRUE(eglTerminate(own));
}

TEST_F(EglX11Test, ConfigsCarryTheScreensTrueColorVisual) {
  const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_WINDOW_BIT | EGL_PIXMAP_BIT | EGL_PBUFFER_BIT,
                            EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig configs[16];
  EGLint n = 0;
  ASSERT_TRUE(eglChooseConfig(edpy, attribs, configs, 16, &n));
  EXPECT_EQ(n, 7);
  const VisualID default_visual = XVisualIDFromVisual(DefaultVisual(dpy, screen));
  for (EGLint i = 0; i < n; ++i) {
    EGLint id = 0, type = 0;
    ASSERT_TRUE(eglGetConfigAttrib(edpy, configs[i], EGL_NATIVE_VISUAL_ID, &id));
    ASSERT_TRUE(eglGetConfigAttrib(edpy, configs[i], EGL_NATIVE_VISUAL_TYPE, &type));
    EXPECT_EQ(static_cast<VisualID>(id), default_visual);
    EXPECT_EQ(type, TrueColor);
  }
}

TEST_F(EglX11Test, WindowSurfaceSwapReachesTheWindow) {
  EGLConfig c = window_config();
  ASSERT_NE(c, nullptr);
  Window w = native_window(c, 64, 48);
  EGLSurface s = eglCreateWindowSurface(edpy, c, static_cast<EGLNativeWindowType>(w), nullptr);
  ASSERT_NE(s, EGL_NO_SURFACE) << std::hex << eglGetError();
  EGLContext ctx = egl_context(c);
  ASSERT_TRUE(eglMakeCurrent(edpy, s, s, ctx));
  EGLint value = 0;
  eglQuerySurface(edpy, s, EGL_WIDTH, &value);
  EXPECT_EQ(value, 64);
  eglQuerySurface(edpy, s, EGL_HEIGHT, &value);
  EXPECT_EQ(value, 48);
  eglQuerySurface(edpy, s, EGL_RENDER_BUFFER, &value);
  EXPECT_EQ(value, EGL_BACK_BUFFER);
  GLint buffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &buffer);
  EXPECT_EQ(buffer, GL_BACK);

  clear_with_corner(0, 0, 1, 1, 0, 0);
  EXPECT_EQ(gl_pixel(0, 0), kRed);
  EXPECT_EQ(gl_pixel(63, 47), kBlue);
  EXPECT_TRUE(eglSwapInterval(edpy, 0));
  ASSERT_TRUE(eglSwapBuffers(edpy, s));
  EXPECT_EQ(x_pixel(w, 0, 47), kRed);
  EXPECT_EQ(x_pixel(w, 9, 38), kRed);
  EXPECT_EQ(x_pixel(w, 10, 37), kBlue);
  EXPECT_EQ(x_pixel(w, 63, 0), kBlue);
  // The front buffer holds the presented frame.
  glReadBuffer(GL_FRONT);
  EXPECT_EQ(gl_pixel(0, 0), kRed);
  EXPECT_TRUE(take_errors().empty());

  // One surface per window.
  EXPECT_EQ(eglCreateWindowSurface(edpy, c, static_cast<EGLNativeWindowType>(w), nullptr),
            EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ALLOC);
}

TEST_F(EglX11Test, PlatformWindowSurfaceTakesAPointerToTheWindow) {
  EGLConfig c = window_config();
  Window w = native_window(c, 20, 20);
  const EGLAttrib attribs[] = {EGL_RENDER_BUFFER, EGL_BACK_BUFFER, EGL_NONE};
  EGLSurface s = eglCreatePlatformWindowSurface(edpy, c, &w, attribs);
  ASSERT_NE(s, EGL_NO_SURFACE);
  ASSERT_TRUE(eglMakeCurrent(edpy, s, s, egl_context(c)));
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(eglSwapBuffers(edpy, s));
  EXPECT_EQ(x_pixel(w, 10, 10), kGreen);
  // The EXT entry point, as eglGetProcAddress gives it.
  auto create_ext = reinterpret_cast<PFNEGLCREATEPLATFORMWINDOWSURFACEEXTPROC>(
      eglGetProcAddress("eglCreatePlatformWindowSurfaceEXT"));
  ASSERT_NE(create_ext, nullptr);
  Window w3 = native_window(c, 8, 8);
  const EGLint ext_attribs[] = {EGL_RENDER_BUFFER, EGL_SINGLE_BUFFER, EGL_NONE};
  EGLSurface s3 = create_ext(edpy, c, &w3, ext_attribs);
  ASSERT_NE(s3, EGL_NO_SURFACE);
  EGLint render_buffer = 0;
  eglQuerySurface(edpy, s3, EGL_RENDER_BUFFER, &render_buffer);
  EXPECT_EQ(render_buffer, EGL_SINGLE_BUFFER);
  EXPECT_NE(eglGetProcAddress("eglCreatePlatformPixmapSurfaceEXT"), nullptr);
  EXPECT_EQ(eglCreatePlatformWindowSurface(edpy, c, nullptr, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_WINDOW);
  const EGLAttrib bad[] = {EGL_WIDTH, 5, EGL_NONE};
  Window w2 = native_window(c, 8, 8);
  EXPECT_EQ(eglCreatePlatformWindowSurface(edpy, c, &w2, bad), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
}

TEST_F(EglX11Test, SingleBufferedWindowSurface) {
  EGLConfig c = window_config();
  Window w = native_window(c, 16, 16);
  const EGLint attribs[] = {EGL_RENDER_BUFFER, EGL_SINGLE_BUFFER, EGL_NONE};
  EGLSurface s = eglCreateWindowSurface(edpy, c, static_cast<EGLNativeWindowType>(w), attribs);
  ASSERT_NE(s, EGL_NO_SURFACE);
  ASSERT_TRUE(eglMakeCurrent(edpy, s, s, egl_context(c)));
  EGLint value = 0;
  eglQuerySurface(edpy, s, EGL_RENDER_BUFFER, &value);
  EXPECT_EQ(value, EGL_SINGLE_BUFFER);
  GLint buffer = 0;
  glGetIntegerv(GL_DRAW_BUFFER, &buffer);
  EXPECT_EQ(buffer, GL_FRONT);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(eglWaitClient());
  EXPECT_EQ(x_pixel(w, 8, 8), kBlue);
}

TEST_F(EglX11Test, FrontBufferDrawingShowsAtFlush) {
  EGLConfig c = window_config();
  Window w = native_window(c, 16, 16);
  EGLSurface s = eglCreateWindowSurface(edpy, c, static_cast<EGLNativeWindowType>(w), nullptr);
  ASSERT_TRUE(eglMakeCurrent(edpy, s, s, egl_context(c)));
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(eglSwapBuffers(edpy, s));
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);  // the back buffer: not shown by a flush
  glFlush();
  EXPECT_EQ(x_pixel(w, 8, 8), kBlue);
  glDrawBuffer(GL_FRONT);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glFlush();
  EXPECT_EQ(x_pixel(w, 8, 8), kGreen);
  glReadBuffer(GL_BACK);
  EXPECT_EQ(gl_pixel(8, 8), kRed);
}

TEST_F(EglX11Test, PixmapSurfaceRendersIntoThePixmap) {
  EGLConfig c = window_config();
  Pixmap p = XCreatePixmap(dpy, RootWindow(dpy, screen), 12, 10, 24);
  EGLSurface s = eglCreatePixmapSurface(edpy, c, static_cast<EGLNativePixmapType>(p), nullptr);
  ASSERT_NE(s, EGL_NO_SURFACE) << std::hex << eglGetError();
  ASSERT_TRUE(eglMakeCurrent(edpy, s, s, egl_context(c)));
  EGLint value = 0;
  eglQuerySurface(edpy, s, EGL_WIDTH, &value);
  EXPECT_EQ(value, 12);
  eglQuerySurface(edpy, s, EGL_RENDER_BUFFER, &value);
  EXPECT_EQ(value, EGL_SINGLE_BUFFER);
  clear_with_corner(0, 1, 0, 1, 0, 0);
  glFinish();
  EXPECT_EQ(x_pixel(p, 0, 9), kRed);
  EXPECT_EQ(x_pixel(p, 11, 0), kGreen);
  EXPECT_TRUE(eglMakeCurrent(edpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_TRUE(eglDestroySurface(edpy, s));
  // The platform call takes a pointer to the Pixmap.
  s = eglCreatePlatformPixmapSurface(edpy, c, &p, nullptr);
  EXPECT_NE(s, EGL_NO_SURFACE);
  EXPECT_TRUE(eglDestroySurface(edpy, s));
  XFreePixmap(dpy, p);
  EXPECT_EQ(eglCreatePixmapSurface(edpy, c, static_cast<EGLNativePixmapType>(p), nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_PIXMAP);
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(EglX11Test, DestroyedWindowIsBadNativeWindow) {
  EGLConfig c = window_config();
  Window w = native_window(c, 16, 16);
  EGLSurface s = eglCreateWindowSurface(edpy, c, static_cast<EGLNativeWindowType>(w), nullptr);
  ASSERT_NE(s, EGL_NO_SURFACE);
  EGLContext ctx = egl_context(c);
  ASSERT_TRUE(eglMakeCurrent(edpy, s, s, ctx));
  XDestroyWindow(dpy, w);
  windows.clear();
  XSync(dpy, False);
  EXPECT_FALSE(eglSwapBuffers(edpy, s));
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_WINDOW);
  ASSERT_TRUE(eglMakeCurrent(edpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_FALSE(eglMakeCurrent(edpy, s, s, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_WINDOW);
  EXPECT_EQ(eglCreateWindowSurface(edpy, c, static_cast<EGLNativeWindowType>(w), nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_BAD_NATIVE_WINDOW);
  // Nothing reached the application's X error handler.
  EXPECT_TRUE(take_errors().empty());
}

TEST_F(EglX11Test, ResizedWindowRendersAtTheNewSize) {
  EGLConfig c = window_config();
  Window w = native_window(c, 40, 30);
  EGLSurface s = eglCreateWindowSurface(edpy, c, static_cast<EGLNativeWindowType>(w), nullptr);
  EGLContext ctx = egl_context(c);
  ASSERT_TRUE(eglMakeCurrent(edpy, s, s, ctx));
  glClearColor(1, 0, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(eglSwapBuffers(edpy, s));
  XResizeWindow(dpy, w, 100, 70);
  XSync(dpy, False);
  // The swap notices the new size; the next frame renders at it.
  ASSERT_TRUE(eglSwapBuffers(edpy, s));
  EGLint width = 0, height = 0;
  eglQuerySurface(edpy, s, EGL_WIDTH, &width);
  eglQuerySurface(edpy, s, EGL_HEIGHT, &height);
  EXPECT_EQ(width, 100);
  EXPECT_EQ(height, 70);
  glViewport(0, 0, 100, 70);
  glClearColor(0, 1, 0, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(gl_pixel(99, 69), kGreen);
  ASSERT_TRUE(eglSwapBuffers(edpy, s));
  EXPECT_EQ(x_pixel(w, 99, 0), kGreen);
  EXPECT_EQ(x_pixel(w, 0, 69), kGreen);
  // And at the next make-current.
  XResizeWindow(dpy, w, 30, 50);
  XSync(dpy, False);
  ASSERT_TRUE(eglMakeCurrent(edpy, s, s, ctx));
  eglQuerySurface(edpy, s, EGL_HEIGHT, &height);
  EXPECT_EQ(height, 50);
  glViewport(0, 0, 30, 50);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  ASSERT_TRUE(eglSwapBuffers(edpy, s));
  EXPECT_EQ(x_pixel(w, 29, 49), kBlue);
  EXPECT_TRUE(take_errors().empty());
}

}  // namespace
}  // namespace pineda_test
