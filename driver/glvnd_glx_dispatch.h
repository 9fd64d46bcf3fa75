// Vendor-neutral dispatch stubs for the GLX extension functions Pineda offers and libglvnd's
// libGLX does not know (glvnd/libglxabi.h, getDispatchAddress and setDispatchIndex).
#pragma once
#include <GL/glx.h>
#include <glvnd/libglxabi.h>

namespace pineda::glx {

// libGLX's callbacks, given to __glx_Main; valid while the vendor library is loaded.
void glvnd_set_exports(const __GLXapiExports* exports);
// The stub for a GLX extension function, or null for any other name.
void* glvnd_dispatch_stub(const char* name);
// libGLX's slot for the function in each vendor's dynamic table.
void glvnd_set_dispatch_index(const char* name, int index);

}  // namespace pineda::glx
