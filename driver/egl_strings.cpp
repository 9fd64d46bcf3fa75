// eglQueryString: the client extensions (EGL_NO_DISPLAY) and a display's strings.
#include "driver/egl_registry.h"
#include "driver/egl_thread.h"
#include "driver/gl_version.h"
#include "glapi/egl_entry_points.h"

namespace pineda::egl {
namespace {

constexpr const char* kClientExtensions =
    "EGL_EXT_client_extensions EGL_EXT_platform_base EGL_EXT_platform_x11 "
    "EGL_KHR_client_get_all_proc_addresses EGL_KHR_platform_x11 EGL_MESA_platform_surfaceless";
constexpr const char* kDisplayExtensions =
    "EGL_EXT_create_context_robustness EGL_KHR_create_context EGL_KHR_get_all_proc_addresses "
    "EGL_KHR_surfaceless_context";

}  // namespace

const char* QueryString(EGLDisplay dpy, EGLint name) {
  if (dpy == EGL_NO_DISPLAY) {
    // EGL 1.5, 3.3: without a display, the client extensions and the client version.
    if (name == EGL_EXTENSIONS) return succeed(kClientExtensions);
    if (name == EGL_VERSION) return succeed("1.5 Pineda");
    return fail<const char*>(EGL_BAD_DISPLAY, nullptr);
  }
  auto lock = Registry::instance().lock();
  if (!initialized_display(dpy)) return nullptr;
  switch (name) {
    case EGL_VENDOR: return succeed("Pineda");
    case EGL_VERSION: return succeed("1.5 Pineda");
    case EGL_CLIENT_APIS: return succeed(driver::kHasGLES ? "OpenGL OpenGL_ES" : "OpenGL");
    case EGL_EXTENSIONS: return succeed(kDisplayExtensions);
    default: return fail<const char*>(EGL_BAD_PARAMETER, nullptr);
  }
}

}  // namespace pineda::egl
