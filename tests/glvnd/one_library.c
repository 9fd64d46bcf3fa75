/* one_library PINEDA_LIB_DIR: a program that reaches Pineda as libEGL's vendor and also loads
 * Pineda's libOSMesa.so.8 and libGL.so.1 by path maps one file: the libpineda.so.0 that the
 * vendor library needs is the object all three names resolve to, so there is one copy of
 * Pineda's state. Exit 0 and "PASS" when so. */
#define _GNU_SOURCE
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <dlfcn.h>
#include <link.h>
#include <stdio.h>
#include <string.h>

struct Loaded {
  int vendor;            /* libEGL_pineda.so.0 is loaded */
  ElfW(Addr) pineda;     /* where libpineda.so.0 is */
};

static int note_object(struct dl_phdr_info* info, size_t size, void* data) {
  struct Loaded* loaded = data;
  const char* slash = strrchr(info->dlpi_name, '/');
  const char* base = slash ? slash + 1 : info->dlpi_name;
  if (strcmp(base, "libEGL_pineda.so.0") == 0) loaded->vendor = 1;
  if (strcmp(base, "libpineda.so.0") == 0) loaded->pineda = info->dlpi_addr;
  return 0;
}

/* The load address of the object that defines SYMBOL in the library at PATH. */
static ElfW(Addr) base_of(const char* dir, const char* name, const char* symbol) {
  char path[4096];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  void* handle = dlopen(path, RTLD_NOW);
  Dl_info info;
  if (!handle || !dladdr(dlsym(handle, symbol), &info)) return 0;
  return (ElfW(Addr))info.dli_fbase;
}

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL)) {
    printf("FAIL: no surfaceless display\n");
    return 1;
  }
  struct Loaded loaded = {0, 0};
  dl_iterate_phdr(note_object, &loaded);
  if (!loaded.vendor || !loaded.pineda) {
    printf("FAIL: libEGL did not load libEGL_pineda.so.0 and its libpineda.so.0\n");
    return 1;
  }
  ElfW(Addr) pineda = loaded.pineda;
  ElfW(Addr) osmesa = base_of(argv[1], "libOSMesa.so.8", "OSMesaCreateContext");
  ElfW(Addr) gl = base_of(argv[1], "libGL.so.1", "glXCreateContext");
  if (osmesa != pineda || gl != pineda) {
    printf("FAIL: the vendor's libpineda.so.0 at %#lx, libOSMesa.so.8 at %#lx, libGL.so.1 at %#lx\n",
           (unsigned long)pineda, (unsigned long)osmesa, (unsigned long)gl);
    return 1;
  }
  eglTerminate(dpy);
  printf("PASS: one object at %#lx\n", (unsigned long)pineda);
  return 0;
}
