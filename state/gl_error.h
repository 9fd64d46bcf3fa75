// A GL error with the rule it broke, as the checks that return an error (rather than record it)
// give it back: Context::record_error takes both, for the debug message (GL_KHR_debug,
// PINEDA_DEBUG=1). It converts to and from the bare GLenum.
#pragma once
#include <GL/gl.h>

namespace pineda {

struct GlError {
  GLenum code = GL_NO_ERROR;
  const char* why = "";  // a string literal: what broke the rule, never built on an error path
  constexpr GlError(GLenum code = GL_NO_ERROR, const char* why = "") : code(code), why(why) {}
  constexpr operator GLenum() const { return code; }
};

}  // namespace pineda
