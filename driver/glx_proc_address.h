#pragma once
// The GLX functions by name, for glXGetProcAddress and for eglGetProcAddress (one library
// serves every API, and programs such as apitrace's eglretrace resolve glX names through EGL).

namespace pineda::glx {

void* lookup_glx_proc(const char* name);  // nullptr for an unknown name

}  // namespace pineda::glx
