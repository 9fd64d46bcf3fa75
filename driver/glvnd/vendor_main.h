// The vendor entries of libpineda.so.0 (driver/glvnd_*_vendor.cpp) to which the vendor
// libraries hand libglvnd's handshake.
#pragma once
#include <glvnd/libeglabi.h>
#include <glvnd/libglxabi.h>

extern "C" {
Bool pineda_glvnd_glx_main(uint32_t version, const __GLXapiExports* exports,
                           __GLXvendorInfo* vendor, __GLXapiImports* imports);
EGLBoolean pineda_glvnd_egl_main(uint32_t version, const __EGLapiExports* exports,
                                 __EGLvendorInfo* vendor, __EGLapiImports* imports);
}
