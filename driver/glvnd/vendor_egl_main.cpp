// libEGL_pineda.so.0, the EGL vendor library that 50_pineda.json names for libglvnd's libEGL.
// All of Pineda is in libpineda.so.0, which this library needs (see vendor_glx_main.cpp).
#include "driver/glvnd/vendor_main.h"

extern "C" __attribute__((visibility("default"))) EGLBoolean __egl_Main(
    uint32_t version, const __EGLapiExports* exports, __EGLvendorInfo* vendor,
    __EGLapiImports* imports) {
  return pineda_glvnd_egl_main(version, exports, vendor, imports);
}
