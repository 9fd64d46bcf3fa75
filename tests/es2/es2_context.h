// An OpenGL ES 2.0 context (EGL surfaceless platform, EGL_CONTEXT_CLIENT_VERSION 2) current
// on a pbuffer, and small helpers to build programs, through the public API only.
#pragma once
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2.h>
#include <GLES2/gl2ext.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pineda::es2_test {

class Es2Context {
 public:
  explicit Es2Context(int width = 16, int height = 16);
  ~Es2Context();
  Es2Context(const Es2Context&) = delete;
  Es2Context& operator=(const Es2Context&) = delete;

  bool ok() const { return context_ != EGL_NO_CONTEXT && surface_ != EGL_NO_SURFACE; }
  const std::string& error() const { return error_; }
  EGLDisplay display() const { return display_; }
  EGLContext context() const { return context_; }

 private:
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLSurface surface_ = EGL_NO_SURFACE;
  std::string error_;
};

// A linked program of the two sources with `bindings` (attribute name, location) applied;
// 0 on failure, with the log in `log`.
GLuint build_program(const char* vertex, const char* fragment,
                     const std::vector<std::pair<const char*, GLuint>>& bindings, std::string* log = nullptr);

// The RGBA8 pixel at (x, y) of the framebuffer, as 0xRRGGBBAA.
uint32_t read_pixel(int x, int y);

}  // namespace pineda::es2_test
