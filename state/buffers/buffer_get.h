// glGet* of the buffer-object bindings.
#pragma once
#include <GL/gl.h>

namespace pineda {

class Context;

// The buffer name bound for `pname` (GL_ARRAY_BUFFER_BINDING, GL_*_ARRAY_BUFFER_BINDING...);
// false when `pname` is not a buffer binding.
bool query_buffer_binding(const Context& ctx, GLenum pname, GLuint& name);

}  // namespace pineda
