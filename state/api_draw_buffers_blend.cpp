// ARB_draw_buffers_blend: blend factors and equations per draw buffer (glBlendFunciARB,
// glBlendFuncSeparateiARB, glBlendEquationiARB, glBlendEquationSeparateiARB). The blend colour
// stays one for all; glBlendFunc and glBlendEquation set every draw buffer's (api_fragment.cpp);
// the indexed queries are EXT_draw_buffers2's (api_draw_buffers2.cpp).
#include <string>

#include "glapi/gl_entry_points.h"
#include "state/blend_function.h"
#include "state/context.h"
#include "state/draw_buffer_list.h"

namespace pineda::gl {
namespace {

// The ARB spec: INVALID_VALUE for a buffer not below MAX_DRAW_BUFFERS.
bool valid_buffer(Context& ctx, GLuint buf) {
  if (buf < GLuint(kMaxDrawBuffers)) return true;
  ctx.record_error(GL_INVALID_VALUE, [buf] { return "draw buffer " + std::to_string(buf) + " is not below MAX_DRAW_BUFFERS"; });
  return false;
}

}  // namespace

void BlendFuncSeparateiARB(Context& ctx, GLuint buf, GLenum src_rgb, GLenum dst_rgb, GLenum src_alpha,
                           GLenum dst_alpha) {
  if (valid_buffer(ctx, buf)) set_blend_factors(ctx, src_rgb, dst_rgb, src_alpha, dst_alpha, blend_function(ctx, buf));
}

void BlendFunciARB(Context& ctx, GLuint buf, GLenum src, GLenum dst) {
  BlendFuncSeparateiARB(ctx, buf, src, dst, src, dst);
}

void BlendEquationSeparateiARB(Context& ctx, GLuint buf, GLenum mode_rgb, GLenum mode_alpha) {
  if (valid_buffer(ctx, buf)) set_blend_equations(ctx, mode_rgb, mode_alpha, blend_function(ctx, buf));
}

void BlendEquationiARB(Context& ctx, GLuint buf, GLenum mode) { BlendEquationSeparateiARB(ctx, buf, mode, mode); }

}  // namespace pineda::gl
