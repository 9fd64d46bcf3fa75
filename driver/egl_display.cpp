// eglGetDisplay, eglGetPlatformDisplay(EXT), eglInitialize, eglTerminate.
// The only platform is EGL_PLATFORM_SURFACELESS_MESA; EGL_DEFAULT_DISPLAY maps to it.
#include "driver/egl_registry.h"
#include "driver/egl_thread.h"
#include "glapi/egl_entry_points.h"

namespace pineda::egl {
namespace {

template <class Attrib>
EGLDisplay platform_display(EGLenum platform, void* native, const Attrib* attribs) {
  if (platform != EGL_PLATFORM_SURFACELESS_MESA) return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
  if (native != nullptr) return fail(EGL_BAD_PARAMETER, EGL_NO_DISPLAY);
  // The surfaceless platform defines no display attributes.
  if (attribs && attribs[0] != EGL_NONE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_DISPLAY);
  auto lock = Registry::instance().lock();
  return succeed<EGLDisplay>(Registry::instance().get(platform, nullptr));
}

}  // namespace

EGLDisplay GetDisplay(EGLNativeDisplayType display_id) {
  // No native window system: only the default display exists.
  if (display_id != EGL_DEFAULT_DISPLAY) return succeed(EGL_NO_DISPLAY);
  auto lock = Registry::instance().lock();
  return succeed<EGLDisplay>(Registry::instance().get(EGL_PLATFORM_SURFACELESS_MESA, nullptr));
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
