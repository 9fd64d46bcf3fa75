// Pineda as a GLX vendor library of libglvnd (glvnd/libglxabi.h): libGLX_pineda.so.0's
// __glx_Main (driver/glvnd/vendor_glx_main.cpp) hands over to pineda_glvnd_glx_main here, in
// libpineda.so.0, so that the state stays in the one library every name of Pineda maps.
//
// libGLX calls the GLX 1.4 functions through getProcAddress and builds libGLdispatch's GL table
// the same way. For a GLX extension function it does not know (Debian 12's libGLX knows
// glXCreateContextAttribsARB, not the swap-interval ones), getDispatchAddress hands it the
// vendor-neutral stubs of glvnd_glx_dispatch.cpp.
#include "driver/glx_objects.h"

#include <glvnd/libglxabi.h>

#include "driver/glvnd/vendor_main.h"
#include "driver/glvnd_glx_dispatch.h"

namespace pineda::glx {
namespace {

// Pineda draws with plain Xlib requests, so it can serve every screen.
Bool is_screen_supported(Display*, int) { return True; }

void* get_proc_address(const GLubyte* name) {
  return reinterpret_cast<void*>(glXGetProcAddressARB(name));
}

void* get_dispatch_address(const GLubyte* name) {
  return glvnd_dispatch_stub(reinterpret_cast<const char*>(name));
}

void set_dispatch_index(const GLubyte* name, int index) {
  glvnd_set_dispatch_index(reinterpret_cast<const char*>(name), index);
}

}  // namespace
}  // namespace pineda::glx

PINEDA_GLX_EXPORT Bool pineda_glvnd_glx_main(uint32_t version, const __GLXapiExports* exports,
                                             __GLXvendorInfo*, __GLXapiImports* imports) {
  using namespace pineda::glx;
  if (GLX_VENDOR_ABI_GET_MAJOR_VERSION(version) != GLX_VENDOR_ABI_MAJOR_VERSION) return False;
  glvnd_set_exports(exports);
  imports->isScreenSupported = is_screen_supported;
  imports->getProcAddress = get_proc_address;
  imports->getDispatchAddress = get_dispatch_address;
  imports->setDispatchIndex = set_dispatch_index;
  // notifyError and the entry-point patching callbacks are optional.
  imports->notifyError = nullptr;
  imports->isPatchSupported = nullptr;
  imports->initiatePatch = nullptr;
  imports->releasePatch = nullptr;
  imports->patchThreadAttach = nullptr;
  return True;
}
