// glXGetProcAddress(ARB): every implemented GL function and the GLX functions below.
#include "driver/glx_proc_address.h"

#include "driver/glx_objects.h"

#include <cstring>

#include "glapi/proc_table.h"

namespace pineda::glx {
namespace {

struct Entry {
  const char* name;
  void* function;
};

#define PINEDA_GLX_ENTRY(name) {#name, reinterpret_cast<void*>(&name)}

const Entry kGlxFunctions[] = {
    PINEDA_GLX_ENTRY(glXChooseFBConfig),
    PINEDA_GLX_ENTRY(glXChooseVisual),
    PINEDA_GLX_ENTRY(glXCopyContext),
    PINEDA_GLX_ENTRY(glXCreateContext),
    PINEDA_GLX_ENTRY(glXCreateContextAttribsARB),
    PINEDA_GLX_ENTRY(glXCreateGLXPixmap),
    PINEDA_GLX_ENTRY(glXCreateNewContext),
    PINEDA_GLX_ENTRY(glXCreatePbuffer),
    PINEDA_GLX_ENTRY(glXCreatePixmap),
    PINEDA_GLX_ENTRY(glXCreateWindow),
    PINEDA_GLX_ENTRY(glXDestroyContext),
    PINEDA_GLX_ENTRY(glXDestroyGLXPixmap),
    PINEDA_GLX_ENTRY(glXDestroyPbuffer),
    PINEDA_GLX_ENTRY(glXDestroyPixmap),
    PINEDA_GLX_ENTRY(glXDestroyWindow),
    PINEDA_GLX_ENTRY(glXGetClientString),
    PINEDA_GLX_ENTRY(glXGetConfig),
    PINEDA_GLX_ENTRY(glXGetCurrentContext),
    PINEDA_GLX_ENTRY(glXGetCurrentDisplay),
    PINEDA_GLX_ENTRY(glXGetCurrentDrawable),
    PINEDA_GLX_ENTRY(glXGetCurrentReadDrawable),
    PINEDA_GLX_ENTRY(glXGetFBConfigAttrib),
    PINEDA_GLX_ENTRY(glXGetFBConfigs),
    PINEDA_GLX_ENTRY(glXGetProcAddress),
    PINEDA_GLX_ENTRY(glXGetProcAddressARB),
    PINEDA_GLX_ENTRY(glXGetSelectedEvent),
    PINEDA_GLX_ENTRY(glXGetSwapIntervalMESA),
    PINEDA_GLX_ENTRY(glXGetVisualFromFBConfig),
    PINEDA_GLX_ENTRY(glXIsDirect),
    PINEDA_GLX_ENTRY(glXMakeContextCurrent),
    PINEDA_GLX_ENTRY(glXMakeCurrent),
    PINEDA_GLX_ENTRY(glXQueryContext),
    PINEDA_GLX_ENTRY(glXQueryDrawable),
    PINEDA_GLX_ENTRY(glXQueryExtension),
    PINEDA_GLX_ENTRY(glXQueryExtensionsString),
    PINEDA_GLX_ENTRY(glXQueryServerString),
    PINEDA_GLX_ENTRY(glXQueryVersion),
    PINEDA_GLX_ENTRY(glXSelectEvent),
    PINEDA_GLX_ENTRY(glXSwapBuffers),
    PINEDA_GLX_ENTRY(glXSwapIntervalEXT),
    PINEDA_GLX_ENTRY(glXSwapIntervalMESA),
    PINEDA_GLX_ENTRY(glXSwapIntervalSGI),
    PINEDA_GLX_ENTRY(glXUseXFont),
    PINEDA_GLX_ENTRY(glXWaitGL),
    PINEDA_GLX_ENTRY(glXWaitX),
};

#undef PINEDA_GLX_ENTRY

void* lookup(const GLubyte* name) {
  if (!name) return nullptr;
  const char* n = reinterpret_cast<const char*>(name);
  if (std::strncmp(n, "glX", 3) == 0) return lookup_glx_proc(n);
  return glapi::lookup_gl_proc(n);
}

}  // namespace

void* lookup_glx_proc(const char* name) {
  for (const Entry& e : kGlxFunctions)
    if (std::strcmp(e.name, name) == 0) return e.function;
  return nullptr;
}

}  // namespace pineda::glx

PINEDA_GLX_EXPORT __GLXextFuncPtr glXGetProcAddressARB(const GLubyte* name) {
  return reinterpret_cast<__GLXextFuncPtr>(pineda::glx::lookup(name));
}

PINEDA_GLX_EXPORT void (*glXGetProcAddress(const GLubyte* name))(void) {
  return reinterpret_cast<void (*)(void)>(pineda::glx::lookup(name));
}
