#include "state/render_mode_get.h"

#include "state/context.h"

namespace pineda {

bool query_render_mode(const Context& ctx, GLenum pname, RenderModeValue& out) {
  const RenderModeState& rm = ctx.render_mode;
  switch (pname) {
    case GL_RENDER_MODE: out = {GLint(rm.mode), true}; return true;
    case GL_NAME_STACK_DEPTH: out = {GLint(rm.names.size()), false}; return true;
    case GL_SELECTION_BUFFER_SIZE: out = {rm.select_size, false}; return true;
    case GL_FEEDBACK_BUFFER_SIZE: out = {rm.feedback_size, false}; return true;
    case GL_FEEDBACK_BUFFER_TYPE: out = {GLint(rm.feedback_type), true}; return true;
    default: return false;
  }
}

bool render_mode_pointer(const Context& ctx, GLenum pname, void** out) {
  switch (pname) {
    case GL_SELECTION_BUFFER_POINTER: *out = ctx.render_mode.select_buffer; return true;
    case GL_FEEDBACK_BUFFER_POINTER: *out = ctx.render_mode.feedback_buffer; return true;
    default: return false;
  }
}

}  // namespace pineda
