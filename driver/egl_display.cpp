// eglGetDisplay, eglGetPlatformDisplay(EXT), eglInitialize, eglTerminate.
// Platforms: EGL_PLATFORM_SURFACELESS_MESA and EGL_PLATFORM_X11_KHR (egl_x11.h). As in Mesa,
// eglGetDisplay takes a native display other than EGL_DEFAULT_DISPLAY for an Xlib Display*;
// EGL_DEFAULT_DISPLAY is the surfaceless display unless EGL_PLATFORM=x11 asks for the
// default X display.
#include <cstdlib>
#include <cstring>

#include "driver/egl_config.h"
#include "driver/egl_registry.h"
#include "driver/egl_thread.h"
#include "driver/egl_x11.h"
#include "glapi/egl_entry_points.h"

namespace pineda::egl {
namespace {

constexpr int kDefaultScreen = -1;

EGLDisplay get_display(EGLenum platform, void* native, int screen) {
  auto lock = Registry::instance().lock();
  Display* display = Registry::instance().get(platform, native);
  if (platform == EGL_PLATFORM_X11_KHR && !display->x11) display->screen = screen;
  return succeed<EGLDisplay>(display);
}

template <class Attrib>
EGLDisplay platform_display(EGLenum platform, void* native, const Attrib* attribs) {
  if (platform == EGL_PLATFORM_SURFACELESS_MESA) {
    if (native != nullptr) return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
    // The surfaceless platform defines no display attributes.
    if (attribs && attribs[0] != EGL_NONE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
    return get_display(platform, nullptr, 0);
  }
  if (platform == EGL_PLATFORM_X11_KHR) {
    int screen = kDefaultScreen;
    for (const Attrib* a = attribs; a && a[0] != EGL_NONE; a += 2) {
      if (a[0] != EGL_PLATFORM_X11_SCREEN_KHR) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
      screen = static_cast<int>(a[1]);
    }
    return get_display(platform, native, screen);
  }
  return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
}

bool default_platform_is_x11() {
  const char* platform = std::getenv("EGL_PLATFORM");
  return platform && std::strcmp(platform, "x11") == 0;
}

}  // namespace

EGLDisplay GetDisplay(EGLNativeDisplayType display_id) {
  if (display_id != EGL_DEFAULT_DISPLAY || default_platform_is_x11())
    return get_display(EGL_PLATFORM_X11_KHR, display_id, kDefaultScreen);
  return get_display(EGL_PLATFORM_SURFACELESS_MESA, nullptr, 0);
}

EGLDisplay GetPlatformDisplay(EGLenum platform, void* native_display, const EGLAttrib* attrib_list) {
  return platform_display(platform, native_display, attrib_list);
}

EGLDisplay GetPlatformDisplayEXT(EGLenum platform, void* native_display, const EGLint* attrib_list) {
  return platform_display(platform, native_display, attrib_list);
}

EGLBoolean Initialize(EGLDisplay dpy, EGLint* major, EGLint* minor) {
  auto lock = Registry::instance().lock();
  Display* display = Registry::instance().find(dpy);
  if (!display) return fail(EGL_BAD_DISPLAY, EGL_FALSE);
  if (display->platform == EGL_PLATFORM_X11_KHR) {
    if (!initialize_x11(*display)) return fail(EGL_NOT_INITIALIZED, EGL_FALSE);
  } else if (display->configs.empty()) {
    display->configs = surfaceless_configs();
  }
  // Initializing an initialized display only returns the version again (EGL 1.5, 3.2).
  display->initialized = true;
  if (major) *major = 1;
  if (minor) *minor = 5;
  return succeed(EGL_TRUE);
}

EGLBoolean Terminate(EGLDisplay dpy) {
  auto lock = Registry::instance().lock();
  Display* display = Registry::instance().find(dpy);
  if (!display) return fail(EGL_BAD_DISPLAY, EGL_FALSE);
  // Handles become invalid now; objects still current to a thread live on through the
  // thread's references until it releases them.
  // Freed after the lock is released.
  auto contexts = std::move(display->contexts);
  auto surfaces = std::move(display->surfaces);
  auto syncs = std::move(display->syncs);
  display->contexts.clear();
  display->surfaces.clear();
  display->syncs.clear();
  display->initialized = false;
  lock.unlock();
  return succeed(EGL_TRUE);
}

}  // namespace pineda::egl
