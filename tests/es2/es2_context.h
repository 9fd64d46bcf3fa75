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

#include "tests/es1/egl_context.h"

namespace pineda::es2_test {

// The ES 1.1 tests' EGL context (tests/es1/egl_context.h), asked for ES 2.0 on an ES2 config.
struct Es2Context : es1_test::EglContext {
  explicit Es2Context(int width = 16, int height = 16);
  ~Es2Context();
};

// A linked program of the two sources with `bindings` (attribute name, location) applied;
// 0 on failure, with the log in `log`.
GLuint build_program(const char* vertex, const char* fragment,
                     const std::vector<std::pair<const char*, GLuint>>& bindings, std::string* log = nullptr);

// The RGBA8 pixel at (x, y) of the framebuffer, as 0xRRGGBBAA.
uint32_t read_pixel(int x, int y);

}  // namespace pineda::es2_test
