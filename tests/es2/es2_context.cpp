#include "tests/es2/es2_context.h"

namespace pineda::es2_test {

Es2Context::Es2Context(int width, int height) {
  display_ = eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, nullptr, nullptr)) {
    error_ = "no surfaceless display";
    return;
  }
  const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
                                   EGL_RED_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint n = 0;
  if (!eglChooseConfig(display_, config_attribs, &config, 1, &n) || n < 1) {
    error_ = "no config";
    return;
  }
  if (!eglBindAPI(EGL_OPENGL_ES_API)) {
    error_ = "eglBindAPI failed";
    return;
  }
  const EGLint context_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
  context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attribs);
  if (context_ == EGL_NO_CONTEXT) {
    error_ = "eglCreateContext failed: " + std::to_string(eglGetError());
    return;
  }
  const EGLint surface_attribs[] = {EGL_WIDTH, width, EGL_HEIGHT, height, EGL_NONE};
  surface_ = eglCreatePbufferSurface(display_, config, surface_attribs);
  if (surface_ == EGL_NO_SURFACE) {
    error_ = "eglCreatePbufferSurface failed";
    return;
  }
  if (!eglMakeCurrent(display_, surface_, surface_, context_)) error_ = "eglMakeCurrent failed";
}

Es2Context::~Es2Context() {
  if (display_ == EGL_NO_DISPLAY) return;
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
  if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
  eglBindAPI(EGL_OPENGL_API);
}

namespace {

GLuint compile(GLenum type, const char* source, std::string* log) {
  GLuint s = glCreateShader(type);
  glShaderSource(s, 1, &source, nullptr);
  glCompileShader(s);
  GLint status = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &status);
  if (!status) {
    char buffer[4096] = {};
    glGetShaderInfoLog(s, sizeof(buffer), nullptr, buffer);
    if (log) *log += buffer;
    glDeleteShader(s);
    return 0;
  }
  return s;
}

}  // namespace

GLuint build_program(const char* vertex, const char* fragment,
                     const std::vector<std::pair<const char*, GLuint>>& bindings, std::string* log) {
  const GLuint vs = compile(GL_VERTEX_SHADER, vertex, log);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment, log);
  if (!vs || !fs) return 0;
  const GLuint p = glCreateProgram();
  glAttachShader(p, vs);
  glAttachShader(p, fs);
  for (const auto& [name, location] : bindings) glBindAttribLocation(p, location, name);
  glLinkProgram(p);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint status = 0;
  glGetProgramiv(p, GL_LINK_STATUS, &status);
  if (!status) {
    char buffer[4096] = {};
    glGetProgramInfoLog(p, sizeof(buffer), nullptr, buffer);
    if (log) *log += buffer;
    glDeleteProgram(p);
    return 0;
  }
  return p;
}

uint32_t read_pixel(int x, int y) {
  uint8_t p[4] = {};
  glReadPixels(x, y, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3];
}

}  // namespace pineda::es2_test
