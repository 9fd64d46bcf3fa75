// glGet* of the selection and feedback state.
#pragma once
#include <GL/gl.h>

namespace pineda {

class Context;

struct RenderModeValue {
  GLint value = 0;
  bool is_enum = false;
};

// GL_RENDER_MODE, GL_NAME_STACK_DEPTH, GL_SELECTION_BUFFER_SIZE, GL_FEEDBACK_BUFFER_SIZE and
// GL_FEEDBACK_BUFFER_TYPE; false for any other `pname`.
bool query_render_mode(const Context& ctx, GLenum pname, RenderModeValue& out);

// GL_SELECTION_BUFFER_POINTER and GL_FEEDBACK_BUFFER_POINTER (glGetPointerv).
bool render_mode_pointer(const Context& ctx, GLenum pname, void** out);

}  // namespace pineda
