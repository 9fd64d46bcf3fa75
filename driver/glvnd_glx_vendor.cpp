// __glx_Main: Pineda as a GLX vendor library of libglvnd (glvnd/libglxabi.h).
//
// libGLX_pineda.so.0 is another name of libpineda.so.0 (a link to the same file, like
// libGL.so.1), so a program that reaches Pineda through libglvnd and also through Pineda's own
// names still maps one file and has one copy of the state. A separate thin vendor library could
// not call into libpineda.so.0: its calls to glX* would bind to libglvnd's libGLX, which the
// program loaded first.
//
// libGLX calls the GLX 1.4 functions through getProcAddress and builds libGLdispatch's GL table
// the same way. GLX extension functions are unknown to it: for those, getDispatchAddress hands it
// the vendor-neutral stubs of glvnd_glx_dispatch.cpp.
#include "driver/glx_objects.h"

#include <glvnd/libglxabi.h>

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

PINEDA_GLX_EXPORT Bool __glx_Main(uint32_t version, const __GLXapiExports* exports,
                                  __GLXvendorInfo* vendor, __GLXapiImports* imports) {
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
