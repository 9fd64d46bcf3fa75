// Name -> entry point lookups over the implemented functions only (generated tables),
// shared by eglGetProcAddress, OSMesaGetProcAddress and glXGetProcAddress.
#pragma once

namespace pineda::glapi {

// nullptr for a name Pineda does not implement.
void* lookup_gl_proc(const char* name);
void* lookup_egl_proc(const char* name);

}  // namespace pineda::glapi
