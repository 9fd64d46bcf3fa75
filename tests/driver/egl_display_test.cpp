// EGL displays: getting, initializing, terminating; error codes.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <gtest/gtest.h>

namespace {

TEST(EglDisplay, DefaultDisplayIsSurfacelessDisplay) {
  EGLDisplay dpy = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  ASSERT_NE(dpy, EGL_NO_DISPLAY);
  EXPECT_EQ(eglGetError(), EGL_SUCCESS);
  EXPECT_EQ(eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), dpy);
  EXPECT_EQ(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), dpy);
}

}  // namespace
