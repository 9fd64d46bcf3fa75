/* The GLX extension functions through libglvnd: linked against the system's libGL.so.1 and run
 * with __GLX_VENDOR_LIBRARY_NAME=pineda, glXGetProcAddressARB hands out Pineda's dispatch stubs
 * (driver/glvnd_glx_dispatch.cpp), which must reach Pineda's functions for the right vendor:
 * glXSwapIntervalEXT by drawable, the MESA and SGI swap-interval calls by current context;
 * a context from glXCreateContextAttribsARB must be Pineda's. Run under Xvfb. Exit 0 and "PASS"
 * when all hold. */
#define _GNU_SOURCE
#include <GL/gl.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

static int fail(const char* what) {
  printf("FAIL: %s\n", what);
  return 1;
}

/* The stub lives in libpineda.so.0, loaded by name as the vendor library's dependency (a
 * libGL.so.1 of Pineda's would be the same file under the name libGL.so.1). */
static int from_vendor_library(void (*function)(void)) {
  Dl_info info;
  if (!function || !dladdr((void*)function, &info) || !info.dli_fname) return 0;
  const char* slash = strrchr(info.dli_fname, '/');
  return strcmp(slash ? slash + 1 : info.dli_fname, "libpineda.so.0") == 0;
}

#define GET(type, name) ((type)glXGetProcAddressARB((const GLubyte*)#name))

int main(void) {
  Display* dpy = XOpenDisplay(NULL);
  if (!dpy) return fail("no X display");
  /* libGLX loads a screen's vendor on the first GLX call for the screen; only loaded vendors are
   * asked for GLX extension functions (before that, glXGetProcAddress takes a name for GL's). */
  const int config_attribs[] = {GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT, GLX_RENDER_TYPE, GLX_RGBA_BIT,
                                GLX_DOUBLEBUFFER, True, None};
  int count = 0;
  GLXFBConfig* configs = glXChooseFBConfig(dpy, DefaultScreen(dpy), config_attribs, &count);
  if (!configs || count < 1) return fail("no double-buffered window config");
  PFNGLXCREATECONTEXTATTRIBSARBPROC create_context =
      GET(PFNGLXCREATECONTEXTATTRIBSARBPROC, glXCreateContextAttribsARB);
  PFNGLXSWAPINTERVALEXTPROC swap_interval_ext = GET(PFNGLXSWAPINTERVALEXTPROC, glXSwapIntervalEXT);
  PFNGLXSWAPINTERVALMESAPROC swap_interval_mesa =
      GET(PFNGLXSWAPINTERVALMESAPROC, glXSwapIntervalMESA);
  PFNGLXGETSWAPINTERVALMESAPROC get_swap_interval =
      GET(PFNGLXGETSWAPINTERVALMESAPROC, glXGetSwapIntervalMESA);
  PFNGLXSWAPINTERVALSGIPROC swap_interval_sgi = GET(PFNGLXSWAPINTERVALSGIPROC, glXSwapIntervalSGI);
  /* Debian 12's libGLX dispatches glXCreateContextAttribsARB itself; one that does not know it
   * takes Pineda's stub. Either way the context must be Pineda's. */
  if (!create_context) return fail("no glXCreateContextAttribsARB");
  void (*stubs[])(void) = {(void (*)(void))swap_interval_ext, (void (*)(void))swap_interval_mesa,
                           (void (*)(void))get_swap_interval, (void (*)(void))swap_interval_sgi};
  for (unsigned i = 0; i < sizeof stubs / sizeof stubs[0]; ++i)
    if (!from_vendor_library(stubs[i]))
      return fail("a swap-interval function is not Pineda's stub");

  /* No context current yet: the stubs find no vendor and answer as the extensions say. */
  if (swap_interval_mesa(1) != GLX_BAD_CONTEXT)
    return fail("glXSwapIntervalMESA without a context");
  if (get_swap_interval() != 0) return fail("glXGetSwapIntervalMESA without a context");

  const int context_attribs[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 1, GLX_CONTEXT_MINOR_VERSION_ARB, 5,
                                 None};
  GLXContext context = create_context(dpy, configs[0], NULL, True, context_attribs);
  if (!context) return fail("glXCreateContextAttribsARB");
  XVisualInfo* visual = glXGetVisualFromFBConfig(dpy, configs[0]);
  if (!visual) return fail("no visual for the config");
  Window root = RootWindow(dpy, visual->screen);
  XSetWindowAttributes window_attribs = {0};
  window_attribs.colormap = XCreateColormap(dpy, root, visual->visual, AllocNone);
  Window window = XCreateWindow(dpy, root, 0, 0, 16, 16, 0, visual->depth, InputOutput,
                                visual->visual, CWColormap, &window_attribs);
  /* libGLX knows the context only through the mapping the stub recorded. */
  if (!glXMakeCurrent(dpy, window, context)) return fail("glXMakeCurrent with the new context");
  if (glXGetCurrentContext() != context) return fail("glXGetCurrentContext");
  const char* vendor = (const char*)glGetString(GL_VENDOR);
  if (!vendor || strcmp(vendor, "Pineda") != 0) return fail("GL_VENDOR is not Pineda");

  if (swap_interval_mesa(2) != 0 || get_swap_interval() != 2) return fail("glXSwapIntervalMESA(2)");
  swap_interval_ext(dpy, window, 3);
  if (get_swap_interval() != 3) return fail("glXSwapIntervalEXT(3)");
  if (swap_interval_sgi(1) != 0 || get_swap_interval() != 1) return fail("glXSwapIntervalSGI(1)");
  if (swap_interval_sgi(0) != GLX_BAD_VALUE) return fail("glXSwapIntervalSGI(0) is not BAD_VALUE");

  glXMakeCurrent(dpy, None, NULL);
  glXDestroyContext(dpy, context);
  XDestroyWindow(dpy, window);
  XFree(visual);
  XFree(configs);
  XCloseDisplay(dpy);
  printf("PASS\n");
  return 0;
}
