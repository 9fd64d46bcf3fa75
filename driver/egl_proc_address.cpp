// eglGetProcAddress (EGL and GL functions: EGL_KHR_get_all_proc_addresses; GLX ones too, as
// glvnd's libEGL hands out a pointer for any gl-prefixed name) and eglGetError.
#include "driver/egl_thread.h"
#include "driver/glx_proc_address.h"
#include "glapi/egl_entry_points.h"
#include "glapi/proc_table.h"

namespace pineda::egl {

__eglMustCastToProperFunctionPointerType GetProcAddress(const char* procname) {
  void* proc = glapi::lookup_egl_proc(procname);
  if (!proc) proc = glapi::lookup_gl_proc(procname);
  if (!proc && procname) proc = glx::lookup_glx_proc(procname);
  return succeed(reinterpret_cast<__eglMustCastToProperFunctionPointerType>(proc));
}

EGLint GetError() {
  ThreadState& t = thread_state();
  EGLint error = t.error;
  t.error = EGL_SUCCESS;
  return error;
}

}  // namespace pineda::egl
