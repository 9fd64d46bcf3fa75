// glRenderMode, the selection name stack, glSelectBuffer, glFeedbackBuffer, glPassThrough.
#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/select_feedback.h"

namespace pineda::gl {
namespace {

bool valid_feedback_type(GLenum type) {
  return type == GL_2D || type == GL_3D || type == GL_3D_COLOR || type == GL_3D_COLOR_TEXTURE ||
         type == GL_4D_COLOR_TEXTURE;
}

bool selecting(const Context& ctx) { return ctx.render_mode.mode == GL_SELECT; }

}  // namespace

GLint RenderMode(Context& ctx, GLenum mode) {
  RenderModeState& rm = ctx.render_mode;
  if (mode != GL_RENDER && mode != GL_SELECT && mode != GL_FEEDBACK) {
    ctx.record_error(GL_INVALID_ENUM, "mode is not GL_RENDER, GL_SELECT or GL_FEEDBACK");
    return 0;
  }
  if ((mode == GL_SELECT && (!rm.select_buffer || rm.select_size == 0)) ||
      (mode == GL_FEEDBACK && (!rm.feedback_buffer || rm.feedback_size == 0))) {
    ctx.record_error(GL_INVALID_OPERATION, "the mode has no buffer to write to");  // no buffer to write to
    return 0;
  }
  GLint result = 0;
  if (rm.mode == GL_SELECT) {
    rm.write_hit_record();
    result = rm.select_count > size_t(rm.select_size) ? -1 : rm.hits;
  } else if (rm.mode == GL_FEEDBACK) {
    result = rm.feedback_count > size_t(rm.feedback_size) ? -1 : GLint(rm.feedback_count);
  }
  rm.mode = mode;
  rm.select_count = rm.feedback_count = 0;
  rm.hits = 0;
  rm.hit = false;
  rm.hit_min_z = 1.0;
  rm.hit_max_z = 0.0;
  rm.names.clear();
  return result;
}

void SelectBuffer(Context& ctx, GLsizei size, GLuint* buffer) {
  if (selecting(ctx)) return ctx.record_error(GL_INVALID_OPERATION, "the render mode is GL_SELECT");
  if (size < 0) return ctx.record_error(GL_INVALID_VALUE, "size is negative");
  ctx.render_mode.select_buffer = buffer;
  ctx.render_mode.select_size = buffer ? size : 0;
}

void FeedbackBuffer(Context& ctx, GLsizei size, GLenum type, GLfloat* buffer) {
  if (ctx.render_mode.mode == GL_FEEDBACK)
    return ctx.record_error(GL_INVALID_OPERATION, "the render mode is GL_FEEDBACK");
  if (size < 0) return ctx.record_error(GL_INVALID_VALUE, "size is negative");
  if (!valid_feedback_type(type)) return ctx.record_error(GL_INVALID_ENUM, "type is not a feedback type");
  ctx.render_mode.feedback_buffer = buffer;
  ctx.render_mode.feedback_size = buffer ? size : 0;
  ctx.render_mode.feedback_type = type;
}

// Outside selection the name stack calls do nothing (glInitNames still empties it, as Mesa).
void InitNames(Context& ctx) {
  if (selecting(ctx)) ctx.render_mode.write_hit_record();
  ctx.render_mode.names.clear();
}

void LoadName(Context& ctx, GLuint name) {
  if (!selecting(ctx)) return;
  RenderModeState& rm = ctx.render_mode;
  if (rm.names.empty()) return ctx.record_error(GL_INVALID_OPERATION, "the name stack is empty");
  rm.write_hit_record();
  rm.names.back() = name;
}

void PushName(Context& ctx, GLuint name) {
  if (!selecting(ctx)) return;
  RenderModeState& rm = ctx.render_mode;
  rm.write_hit_record();
  if (rm.names.size() >= kMaxNameStackDepth)
    return ctx.record_error(GL_STACK_OVERFLOW, "the name stack is full (GL_MAX_NAME_STACK_DEPTH)");
  rm.names.push_back(name);
}

void PopName(Context& ctx) {
  if (!selecting(ctx)) return;
  RenderModeState& rm = ctx.render_mode;
  rm.write_hit_record();
  if (rm.names.empty()) return ctx.record_error(GL_STACK_UNDERFLOW, "the name stack is empty");
  rm.names.pop_back();
}

void PassThrough(Context& ctx, GLfloat token) {
  if (ctx.render_mode.mode != GL_FEEDBACK) return;
  ctx.render_mode.feedback_value(GL_PASS_THROUGH_TOKEN);
  ctx.render_mode.feedback_value(token);
}

}  // namespace pineda::gl
