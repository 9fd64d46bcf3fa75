// EGL displays: getting, initializing, terminating; their error codes.
#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <gtest/gtest.h>

#include <thread>

namespace {

EGLDisplay surfaceless() {
  return eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
}

TEST(EglDisplay, DefaultDisplayIsTheSurfacelessDisplay) {
  EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  ASSERT_NE(dpy, EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  EXPECT_EQ(surfaceless(), dpy);
  EXPECT_EQ(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr),
            dpy);
  const EGLAttrib empty[] = {EGL_NONE};
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, empty), dpy);
}

TEST(EglDisplay, UnknownPlatformIsBadParameter) {
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_WAYLAND_KHR, nullptr, nullptr), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_EQ(eglGetPlatformDisplayEXT(0x1234, nullptr, nullptr), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST(EglDisplay, SurfacelessNeedsTheDefaultNativeDisplay) {
  int native = 0;
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, &native, nullptr), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
}

TEST(EglDisplay, DisplayAttributesAreBadAttribute) {
  const EGLAttrib attribs[] = {EGL_WIDTH, 1, EGL_NONE};
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, attribs),
            EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
}

// As in Mesa, another native display is an Xlib Display*: the X11 platform's display for it
// (tests/glx/egl_x11_test.cpp initializes one under Xvfb).
TEST(EglDisplay, NonDefaultNativeDisplayIsAnX11Display) {
  int native = 0;
  EGLDisplay dpy = eglGetDisplay(reinterpret_cast<EGLNativeDisplayType>(&native));
  EXPECT_NE(dpy, EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, &native, nullptr), dpy);
  EXPECT_NE(eglGetDisplay(EGL_DEFAULT_DISPLAY), dpy);
}

TEST(EglDisplay, X11ScreenIsTheOnlyX11DisplayAttribute) {
  const EGLAttrib screen[] = {EGL_PLATFORM_X11_SCREEN_KHR, 0, EGL_NONE};
  EXPECT_NE(eglGetPlatformDisplay(EGL_PLATFORM_X11_KHR, nullptr, screen), EGL_NO_DISPLAY);
  const EGLint bad[] = {EGL_WIDTH, 1, EGL_NONE};
  EXPECT_EQ(eglGetPlatformDisplayEXT(EGL_PLATFORM_X11_EXT, nullptr, bad), EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_BAD_ATTRIBUTE);
}

TEST(EglDisplay, InitializeReturnsVersion15) {
  EGLint major = 0, minor = 0;
  ASSERT_TRUE(eglInitialize(surfaceless(), &major, &minor));
  EXPECT_EQ(major, 1);
  EXPECT_EQ(minor, 5);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  // Again: only the version is returned again.
  major = minor = 0;
  ASSERT_TRUE(eglInitialize(surfaceless(), &major, &minor));
  EXPECT_EQ(major, 1);
  EXPECT_EQ(minor, 5);
}

TEST(EglDisplay, BadDisplayHandles) {
  int junk = 0;
  EGLDisplay bad = reinterpret_cast<EGLDisplay>(&junk);
  EGLint n = 0;
  EXPECT_FALSE(eglInitialize(bad, nullptr, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_FALSE(eglInitialize(EGL_NO_DISPLAY, nullptr, nullptr));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_FALSE(eglTerminate(bad));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_FALSE(eglGetConfigs(bad, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_EQ(eglQueryString(bad, EGL_VENDOR), nullptr);
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_FALSE(eglMakeCurrent(bad, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
  EXPECT_EQ(eglCreateContext(bad, nullptr, EGL_NO_CONTEXT, nullptr), EGL_NO_CONTEXT);
  EXPECT_EQ(eglGetError(), EGL_BAD_DISPLAY);
}

TEST(EglDisplay, TerminatedDisplayIsNotInitialized) {
  EGLDisplay dpy = surfaceless();
  ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
  ASSERT_TRUE(eglTerminate(dpy));
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  // Terminating twice is allowed.
  EXPECT_TRUE(eglTerminate(dpy));

  EGLint n = 0;
  EXPECT_FALSE(eglGetConfigs(dpy, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  EXPECT_FALSE(eglChooseConfig(dpy, nullptr, nullptr, 0, &n));
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  EXPECT_EQ(eglQueryString(dpy, EGL_VENDOR), nullptr);
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  EXPECT_EQ(eglCreatePbufferSurface(dpy, nullptr, nullptr), EGL_NO_SURFACE);
  EXPECT_EQ(eglGetError(), EGL_NOT_INITIALIZED);
  // Releasing is allowed on a terminated display.
  EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);

  ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
  EXPECT_TRUE(eglGetConfigs(dpy, nullptr, 0, &n));
}

TEST(EglDisplay, TerminateInvalidatesHandlesButKeepsCurrentContextAlive) {
  EGLDisplay dpy = surfaceless();
  ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
  ASSERT_TRUE(eglBindAPI(EGL_OPENGL_API));
  const EGLint attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                            EGL_NONE};
  EGLConfig cfg;
  EGLint n = 0;
  ASSERT_TRUE(eglChooseConfig(dpy, attribs, &cfg, 1, &n));
  ASSERT_EQ(n, 1);
  EGLContext ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, nullptr);
  ASSERT_NE(ctx, EGL_NO_CONTEXT);
  ASSERT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx));

  ASSERT_TRUE(eglTerminate(dpy));
  EXPECT_EQ(eglGetCurrentContext(), ctx);
  ASSERT_TRUE(eglInitialize(dpy, nullptr, nullptr));
  EXPECT_FALSE(eglDestroyContext(dpy, ctx));
  EXPECT_EQ(eglGetError(), EGL_BAD_CONTEXT);
  EXPECT_TRUE(eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT));
  EXPECT_EQ(eglGetCurrentContext(), EGL_NO_CONTEXT);
}

TEST(EglDisplay, ErrorIsPerThreadAndResetByGetError) {
  EXPECT_EQ(eglGetPlatformDisplay(0x1234, nullptr, nullptr), EGL_NO_DISPLAY);
  EGLint other = -1;
  std::thread([&] { other = eglGetError(); }).join();
  EXPECT_EQ(other, EGL_SUCCESS);
  EXPECT_EQ(eglGetError(), EGL_BAD_PARAMETER);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
}

}  // namespace
