// EXT_draw_buffers2: a colour write mask and a blend enable per draw buffer
// (glColorMaskIndexedEXT, glEnable/Disable/IsEnabledIndexedEXT for BLEND, and their indexed
// queries, which also answer ARB_draw_buffers_blend's factors and equations per draw buffer).
// glColorMask and glEnable(GL_BLEND) set every draw buffer's; the unindexed queries return draw
// buffer 0's.
#include <type_traits>

#include "glapi/gl_entry_points.h"
#include "state/blend_function.h"
#include "state/context.h"
#include "state/debug/debug_output.h"
#include "state/draw_buffer_list.h"

namespace pineda {
namespace {

bool& blend_enable(Context& ctx, GLuint index) {
  raster::DrawState& s = ctx.draw_state;
  return index == 0 ? s.blend : s.more_targets[index - 1].blend;
}

std::array<bool, 4>& color_mask(Context& ctx, GLuint index) {
  raster::DrawState& s = ctx.draw_state;
  return index == 0 ? s.color_write : s.more_targets[index - 1].color_write;
}

// The draw buffer `index` names, or an error recorded: the indexed state is BLEND (and, for the
// queries, COLOR_WRITEMASK and the blend factors and equations); the index is below
// MAX_DRAW_BUFFERS.
bool indexed_state(Context& ctx, GLenum target, GLuint index, bool queried_too) {
  if (target != GL_BLEND && !(queried_too && (target == GL_COLOR_WRITEMASK || blend_function_state(target)))) {
    ctx.record_error(GL_INVALID_ENUM, [target] { return "no indexed state " + hex_enum(target); });
    return false;
  }
  if (index >= GLuint(kMaxDrawBuffers)) {
    ctx.record_error(GL_INVALID_VALUE, [index] { return "draw buffer " + std::to_string(index) + " is not below MAX_DRAW_BUFFERS"; });
    return false;
  }
  return true;
}

// The indexed value as integers: the four mask components, the enable, or the factor or equation.
template <typename T>
void get_indexed(Context& ctx, GLenum target, GLuint index, T* data) {
  if (!indexed_state(ctx, target, index, true) || !data) return;
  if (target == GL_BLEND) {
    data[0] = blend_enable(ctx, index) ? 1 : 0;
    return;
  }
  if (blend_function_state(target)) {
    const GLenum e = blend_function_enum(blend_function(ctx, index), target);
    data[0] = std::is_same_v<T, GLboolean> ? T(e != 0) : T(e);
    return;
  }
  const std::array<bool, 4>& mask = color_mask(ctx, index);
  for (size_t c = 0; c < 4; ++c) data[c] = mask[c] ? 1 : 0;
}

}  // namespace
}  // namespace pineda

namespace pineda::gl {

void ColorMaskIndexedEXT(Context& ctx, GLuint index, GLboolean r, GLboolean g, GLboolean b, GLboolean a) {
  if (!indexed_state(ctx, GL_COLOR_WRITEMASK, index, true)) return;
  color_mask(ctx, index) = {r != GL_FALSE, g != GL_FALSE, b != GL_FALSE, a != GL_FALSE};
}

void EnableIndexedEXT(Context& ctx, GLenum target, GLuint index) {
  if (indexed_state(ctx, target, index, false)) blend_enable(ctx, index) = true;
}

void DisableIndexedEXT(Context& ctx, GLenum target, GLuint index) {
  if (indexed_state(ctx, target, index, false)) blend_enable(ctx, index) = false;
}

GLboolean IsEnabledIndexedEXT(Context& ctx, GLenum target, GLuint index) {
  if (!indexed_state(ctx, target, index, false)) return GL_FALSE;
  return blend_enable(ctx, index) ? GL_TRUE : GL_FALSE;
}

void GetBooleanIndexedvEXT(Context& ctx, GLenum target, GLuint index, GLboolean* data) {
  get_indexed(ctx, target, index, data);
}

void GetIntegerIndexedvEXT(Context& ctx, GLenum target, GLuint index, GLint* data) {
  get_indexed(ctx, target, index, data);
}

}  // namespace pineda::gl
