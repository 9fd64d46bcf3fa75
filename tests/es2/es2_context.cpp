#include "tests/es2/es2_context.h"

namespace pineda::es2_test {

namespace {
constexpr EGLint kClientVersion2[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
}

Es2Context::Es2Context(int width, int height)
    : EglContext(EGL_OPENGL_ES_API, kClientVersion2, width, height, EGL_OPENGL_ES2_BIT) {}

// Later code in the same thread binds desktop GL again, as before the ES 2.0 context.
Es2Context::~Es2Context() { eglBindAPI(EGL_OPENGL_API); }

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
