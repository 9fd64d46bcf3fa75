/* A headless EGL program linked like any other against the system's libEGL.so.1 and
 * libOpenGL.so.0 (libglvnd). Run with __EGL_VENDOR_LIBRARY_FILENAMES naming Pineda's vendor file,
 * it must reach Pineda through libEGL: the surfaceless platform, a pbuffer with exact pixels,
 * a GL function known only by eglGetProcAddress, and a context current without a surface.
 * Exit 0 and "PASS" when all hold; otherwise "FAIL: ..." and 1. */
#define _GNU_SOURCE
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <dlfcn.h>
#include <link.h>
#include <stdio.h>
#include <string.h>

enum { kSize = 8 };

static int fail(const char* what) {
  printf("FAIL: %s (EGL error 0x%x)\n", what, eglGetError());
  return 1;
}

static int has_word(const char* list, const char* word) {
  size_t n = strlen(word);
  for (const char* p = list ? strstr(list, word) : NULL; p; p = strstr(p + 1, word))
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return 1;
  return 0;
}

struct Loaded {
  const char* libegl;
  int pineda_vendor;
};

static int note_object(struct dl_phdr_info* info, size_t size, void* data) {
  struct Loaded* loaded = data;
  const char* slash = strrchr(info->dlpi_name, '/');
  const char* base = slash ? slash + 1 : info->dlpi_name;
  if (strcmp(base, "libEGL.so.1") == 0) loaded->libegl = info->dlpi_name;
  if (strcmp(base, "libEGL_pineda.so.0") == 0) loaded->pineda_vendor = 1;
  return 0;
}

/* The pbuffer: blue, with red in the lower-left quadrant (a rectangle whose edges lie between
 * pixel centres, so coverage is exact). glWindowPos2iARB, which libOpenGL does not export, then
 * puts one green pixel at (6, 1) with glDrawPixels. */
static int check_pixels(void) {
  typedef void (*WindowPos2i)(GLint, GLint);
  WindowPos2i window_pos = (WindowPos2i)eglGetProcAddress("glWindowPos2iARB");
  if (!window_pos) return fail("eglGetProcAddress(glWindowPos2iARB) is NULL");
  glViewport(0, 0, kSize, kSize);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  glColor3f(1, 0, 0);
  glRectf(-1, -1, 0, 0);
  const GLubyte green[4] = {0, 255, 0, 255};
  window_pos(6, 1);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, green);
  GLubyte pixels[kSize * kSize * 4];
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  if (glGetError() != GL_NO_ERROR) return fail("a GL error");
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const GLubyte* p = pixels + 4 * (y * kSize + x);
      GLubyte expected[4] = {0, 0, 255, 255};
      if (x < kSize / 2 && y < kSize / 2) expected[0] = 255, expected[2] = 0;
      if (x == 6 && y == 1) expected[1] = 255, expected[2] = 0;
      if (memcmp(p, expected, 4) != 0) {
        printf("FAIL: pixel %d,%d is %d %d %d %d, expected %d %d %d %d\n", x, y, p[0], p[1], p[2],
               p[3], expected[0], expected[1], expected[2], expected[3]);
        return 1;
      }
    }
  }
  return 0;
}

int main(void) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_word(client, "EGL_MESA_platform_surfaceless"))
    return fail("libEGL's client extensions lack EGL_MESA_platform_surfaceless");
  EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (dpy == EGL_NO_DISPLAY) return fail("no surfaceless display");
  if (!eglInitialize(dpy, NULL, NULL)) return fail("eglInitialize");
  const char* vendor = eglQueryString(dpy, EGL_VENDOR);
  if (!vendor || strcmp(vendor, "Pineda") != 0) return fail("the EGL vendor is not Pineda");
  if (!eglBindAPI(EGL_OPENGL_API)) return fail("eglBindAPI(EGL_OPENGL_API)");
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RED_SIZE, 8,
                                   EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                   EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config;
  EGLint count = 0;
  if (!eglChooseConfig(dpy, config_attribs, &config, 1, &count) || count < 1)
    return fail("no RGBA8 pbuffer config");
  const EGLint pbuffer_attribs[] = {EGL_WIDTH, kSize, EGL_HEIGHT, kSize, EGL_NONE};
  EGLSurface pbuffer = eglCreatePbufferSurface(dpy, config, pbuffer_attribs);
  if (pbuffer == EGL_NO_SURFACE) return fail("eglCreatePbufferSurface");
  EGLContext context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, NULL);
  if (context == EGL_NO_CONTEXT) return fail("eglCreateContext");
  if (!eglMakeCurrent(dpy, pbuffer, pbuffer, context)) return fail("eglMakeCurrent(pbuffer)");
  const char* gl_vendor = (const char*)glGetString(GL_VENDOR);
  if (!gl_vendor || strcmp(gl_vendor, "Pineda") != 0) return fail("GL_VENDOR is not Pineda");
  if (check_pixels()) return 1;
  if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, context))
    return fail("eglMakeCurrent without a surface (EGL_KHR_surfaceless_context)");
  if (eglGetCurrentContext() != context) return fail("eglGetCurrentContext");
  glClearColor(1, 1, 1, 1);
  if (glGetError() != GL_NO_ERROR) return fail("a GL error while surfaceless");
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroySurface(dpy, pbuffer);
  eglDestroyContext(dpy, context);
  eglTerminate(dpy);

  /* Pineda came as libEGL's vendor, not as a libEGL.so.1 of its own. */
  struct Loaded loaded = {NULL, 0};
  dl_iterate_phdr(note_object, &loaded);
  if (!loaded.pineda_vendor) return fail("libEGL_pineda.so.0 is not loaded");
  if (!loaded.libegl) return fail("libEGL.so.1 is not loaded");
  /* Of the two, only Pineda's libEGL.so.1 (a name of libpineda.so.0) has Pineda's entries. */
  void* libegl = dlopen(loaded.libegl, RTLD_LAZY | RTLD_NOLOAD);
  if (!libegl || dlsym(libegl, "pineda_glvnd_egl_main")) {
    printf("FAIL: libEGL.so.1 (%s) is Pineda's, not libglvnd's\n", loaded.libegl);
    return 1;
  }
  printf("PASS: Pineda through %s\n", loaded.libegl);
  return 0;
}
