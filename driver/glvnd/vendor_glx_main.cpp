// libGLX_pineda.so.0, the GLX vendor library libglvnd's libGLX loads for
// __GLX_VENDOR_LIBRARY_NAME=pineda. All of Pineda is in libpineda.so.0, which this library
// needs: whichever names a program loads Pineda by, the loader maps that one file once.
#include "driver/glvnd/vendor_main.h"

extern "C" __attribute__((visibility("default"))) Bool __glx_Main(uint32_t version,
                                                                  const __GLXapiExports* exports,
                                                                  __GLXvendorInfo* vendor,
                                                                  __GLXapiImports* imports) {
  return pineda_glvnd_glx_main(version, exports, vendor, imports);
}
