// Pineda as an EGL vendor library of libglvnd (glvnd/libeglabi.h): libEGL_pineda.so.0's
// __egl_Main (driver/glvnd/vendor_egl_main.cpp) hands over to pineda_glvnd_egl_main here, in
// libpineda.so.0.
//
// libEGL calls every core EGL function and the EXT platform-surface functions through
// getProcAddress and builds libGLdispatch's GL table the same way. Pineda offers no EGL display
// extension function beyond those, so it has no dispatch stubs for libEGL to ask for.
#include <glvnd/libeglabi.h>

#include "driver/gl_version.h"
#include "driver/glvnd/vendor_main.h"
#include "glapi/proc_table.h"

#define PINEDA_EGL_VENDOR_EXPORT extern "C" __attribute__((visibility("default")))

namespace pineda::egl {
namespace {

// libEGL merges each vendor's platforms into the client extension string.
constexpr const char* kPlatformExtensions =
    "EGL_EXT_platform_x11 EGL_KHR_platform_x11 EGL_MESA_platform_surfaceless";

// EGL_NONE: eglGetDisplay, whose native display libEGL could not place on a platform.
EGLDisplay get_platform_display(EGLenum platform, void* native, const EGLAttrib* attribs) {
  if (platform == EGL_NONE) return eglGetDisplay(static_cast<EGLNativeDisplayType>(native));
  return eglGetPlatformDisplay(platform, native, attribs);
}

EGLBoolean supports_api(EGLenum api) {
  return api == EGL_OPENGL_API || (api == EGL_OPENGL_ES_API && driver::kHasGLES);
}

const char* vendor_string(int name) {
  return name == __EGL_VENDOR_STRING_PLATFORM_EXTENSIONS ? kPlatformExtensions : nullptr;
}

void* get_proc_address(const char* name) {
  void* proc = glapi::lookup_egl_proc(name);
  return proc ? proc : glapi::lookup_gl_proc(name);
}

void* get_dispatch_address(const char*) { return nullptr; }

void set_dispatch_index(const char*, int) {}

}  // namespace
}  // namespace pineda::egl

PINEDA_EGL_VENDOR_EXPORT EGLBoolean pineda_glvnd_egl_main(uint32_t version,
                                                          const __EGLapiExports*, __EGLvendorInfo*,
                                                          __EGLapiImports* imports) {
  using namespace pineda::egl;
  if (EGL_VENDOR_ABI_GET_MAJOR_VERSION(version) != EGL_VENDOR_ABI_MAJOR_VERSION) return EGL_FALSE;
  imports->getPlatformDisplay = get_platform_display;
  imports->getSupportsAPI = supports_api;
  imports->getVendorString = vendor_string;
  imports->getProcAddress = get_proc_address;
  imports->getDispatchAddress = get_dispatch_address;
  imports->setDispatchIndex = set_dispatch_index;
  // The entry-point patching callbacks and findNativeDisplayPlatform are optional; libEGL's own
  // guess places an Xlib Display* on the X11 platform.
  imports->isPatchSupported = nullptr;
  imports->initiatePatch = nullptr;
  imports->releasePatch = nullptr;
  imports->patchThreadAttach = nullptr;
  return EGL_TRUE;
}
