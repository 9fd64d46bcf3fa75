// glXQueryVersion, glXQueryExtension and the strings: glXQueryExtensionsString,
// glXQueryServerString, glXGetClientString.
//
// Pineda's GLX lives entirely in the client: the "server" strings describe it too, and the
// server's own GLX extension is needed only for its opcode and error base.
#include "driver/glx_objects.h"

#include "driver/glx_registry.h"

namespace pineda::glx {
namespace {

constexpr const char* kVendor = "Pineda";
constexpr const char* kVersion = "1.4";
constexpr const char* kExtensions =
    "GLX_ARB_create_context GLX_ARB_create_context_profile GLX_ARB_create_context_robustness "
    "GLX_ARB_get_proc_address GLX_EXT_create_context_es2_profile GLX_EXT_create_context_es_profile "
    "GLX_EXT_swap_control GLX_MESA_swap_control GLX_SGI_swap_control";

const char* string_of(int name) {
  switch (name) {
    case GLX_VENDOR: return kVendor;
    case GLX_VERSION: return kVersion;
    case GLX_EXTENSIONS: return kExtensions;
    default: return nullptr;
  }
}

}  // namespace
}  // namespace pineda::glx

using namespace pineda::glx;

PINEDA_GLX_EXPORT Bool glXQueryVersion(Display* dpy, int* major, int* minor) {
  if (!dpy) return False;
  if (major) *major = 1;
  if (minor) *minor = 4;
  return True;
}

PINEDA_GLX_EXPORT Bool glXQueryExtension(Display* dpy, int* error_base, int* event_base) {
  if (!dpy) return False;
  auto lock = Registry::instance().lock();
  DisplayState* d = Registry::instance().get(dpy);
  if (error_base) *error_base = d->error_base;
  if (event_base) *event_base = d->event_base;
  return True;
}

PINEDA_GLX_EXPORT const char* glXQueryExtensionsString(Display* dpy, int screen) {
  if (!dpy || screen < 0 || screen >= ScreenCount(dpy)) return nullptr;
  return kExtensions;
}

PINEDA_GLX_EXPORT const char* glXQueryServerString(Display* dpy, int screen, int name) {
  if (!dpy || screen < 0 || screen >= ScreenCount(dpy)) return nullptr;
  return string_of(name);
}

PINEDA_GLX_EXPORT const char* glXGetClientString(Display* dpy, int name) { return string_of(name); }
