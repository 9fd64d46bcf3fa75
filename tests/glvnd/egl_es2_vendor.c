/* OpenGL ES 2.0 through libglvnd: a program linked against the system's libEGL.so.1 and
 * libGLESv2.so.2, run with __EGL_VENDOR_LIBRARY_FILENAMES naming Pineda's vendor file, gets an
 * ES 2.0 context from Pineda (EGL_CONTEXT_CLIENT_VERSION 2) and draws with a shader program
 * through libGLESv2's dispatch: exact pixels. Exit 0 and "PASS" when all hold; otherwise
 * "FAIL: ..." and 1. */
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2.h>
#include <stdio.h>
#include <string.h>

enum { kSize = 8 };

static int fail(const char* what) {
  printf("FAIL: %s (EGL error 0x%x, GL error 0x%x)\n", what, eglGetError(), glGetError());
  return 1;
}

static GLuint shader(GLenum type, const char* source) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, NULL);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  return ok ? s : 0;
}

int main(void) {
  EGLDisplay dpy = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL);
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, NULL, NULL)) return fail("no surfaceless display");
  const char* vendor = eglQueryString(dpy, EGL_VENDOR);
  if (!vendor || strcmp(vendor, "Pineda") != 0) return fail("the EGL vendor is not Pineda");
  if (!eglBindAPI(EGL_OPENGL_ES_API)) return fail("eglBindAPI(EGL_OPENGL_ES_API)");
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
                                   EGL_RED_SIZE, 8, EGL_NONE};
  EGLConfig config;
  EGLint count = 0;
  if (!eglChooseConfig(dpy, config_attribs, &config, 1, &count) || count < 1) return fail("no ES2 config");
  const EGLint pbuffer_attribs[] = {EGL_WIDTH, kSize, EGL_HEIGHT, kSize, EGL_NONE};
  EGLSurface pbuffer = eglCreatePbufferSurface(dpy, config, pbuffer_attribs);
  const EGLint context_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
  EGLContext context = eglCreateContext(dpy, config, EGL_NO_CONTEXT, context_attribs);
  if (pbuffer == EGL_NO_SURFACE || context == EGL_NO_CONTEXT) return fail("pbuffer or context");
  if (!eglMakeCurrent(dpy, pbuffer, pbuffer, context)) return fail("eglMakeCurrent");
  const char* version = (const char*)glGetString(GL_VERSION);
  if (!version || strncmp(version, "OpenGL ES 2.0 Pineda", 20) != 0) return fail("GL_VERSION is not Pineda's ES 2.0");
  GLuint vs = shader(GL_VERTEX_SHADER, "attribute vec2 p; void main() { gl_Position = vec4(p, 0.0, 1.0); }");
  GLuint fs = shader(GL_FRAGMENT_SHADER, "precision mediump float; uniform vec4 c; void main() { gl_FragColor = c; }");
  if (!vs || !fs) return fail("a shader does not compile");
  GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glLinkProgram(program);
  GLint linked = 0;
  glGetProgramiv(program, GL_LINK_STATUS, &linked);
  if (!linked) return fail("the program does not link");
  glUseProgram(program);
  glUniform4f(glGetUniformLocation(program, "c"), 1.f, 0.f, 1.f, 1.f);
  glClearColor(0, 0, 1, 1);
  glClear(GL_COLOR_BUFFER_BIT);
  const float left_half[] = {-1, -1, 0, -1, 0, 1, -1, -1, 0, 1, -1, 1};
  const GLint p = glGetAttribLocation(program, "p");
  glVertexAttribPointer((GLuint)p, 2, GL_FLOAT, GL_FALSE, 0, left_half);
  glEnableVertexAttribArray((GLuint)p);
  glDrawArrays(GL_TRIANGLES, 0, 6);
  GLubyte pixels[kSize * kSize * 4];
  glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
  if (glGetError() != GL_NO_ERROR) return fail("a GL error");
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const GLubyte* q = pixels + 4 * (y * kSize + x);
      const GLubyte expected[4] = {x < kSize / 2 ? 255 : 0, 0, 255, 255};
      if (memcmp(q, expected, 4) != 0) {
        printf("FAIL: pixel %d,%d is %d %d %d %d\n", x, y, q[0], q[1], q[2], q[3]);
        return 1;
      }
    }
  eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroySurface(dpy, pbuffer);
  eglDestroyContext(dpy, context);
  eglTerminate(dpy);
  printf("PASS: OpenGL ES 2.0 from Pineda through libglvnd\n");
  return 0;
}
