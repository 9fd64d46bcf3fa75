// State that shapes primitives: viewport, depth range, culling, polygon mode and offset,
// point size, line width, shading, hints.
#include <algorithm>
#include <cmath>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/enum_translate.h"
#include "state/limits.h"

namespace pineda::gl {

void Viewport(Context& ctx, GLint x, GLint y, GLsizei width, GLsizei height) {
  if (width < 0 || height < 0) return ctx.record_error(GL_INVALID_VALUE, "width or height is negative");
  ctx.viewport.x = x;
  ctx.viewport.y = y;
  ctx.viewport.width = std::min<GLsizei>(width, kMaxViewportDim);
  ctx.viewport.height = std::min<GLsizei>(height, kMaxViewportDim);
}

void DepthRange(Context& ctx, GLdouble near_val, GLdouble far_val) {
  auto clamp01 = [](double v) { return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; };
  ctx.viewport.near_z = clamp01(near_val);
  ctx.viewport.far_z = clamp01(far_val);
}

void CullFace(Context& ctx, GLenum mode) {
  if (mode != GL_FRONT && mode != GL_BACK && mode != GL_FRONT_AND_BACK)
    return ctx.record_error(GL_INVALID_ENUM, "mode is not GL_FRONT, GL_BACK or GL_FRONT_AND_BACK");
  ctx.cull_face_mode = mode;
  ctx.draw_state.cull_front = mode != GL_BACK;
  ctx.draw_state.cull_back = mode != GL_FRONT;
}

void FrontFace(Context& ctx, GLenum mode) {
  if (mode != GL_CW && mode != GL_CCW) return ctx.record_error(GL_INVALID_ENUM, "mode is not GL_CW or GL_CCW");
  ctx.front_face = mode;
  ctx.draw_state.front_ccw = mode == GL_CCW;
}

void PolygonMode(Context& ctx, GLenum face, GLenum mode) {
  raster::PolygonMode m;
  if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK)
    return ctx.record_error(GL_INVALID_ENUM, "face is not GL_FRONT, GL_BACK or GL_FRONT_AND_BACK");
  if (!to_polygon_mode(mode, m)) return ctx.record_error(GL_INVALID_ENUM, "mode is not GL_POINT, GL_LINE or GL_FILL");
  if (face != GL_BACK) {
    ctx.polygon_mode_front = mode;
    ctx.draw_state.polygon_front = m;
  }
  if (face != GL_FRONT) {
    ctx.polygon_mode_back = mode;
    ctx.draw_state.polygon_back = m;
  }
}

void PolygonOffset(Context& ctx, GLfloat factor, GLfloat units) {
  ctx.draw_state.offset_factor = factor;
  ctx.draw_state.offset_units = units;
}

void PointSize(Context& ctx, GLfloat size) {
  if (!(size > 0.f)) return ctx.record_error(GL_INVALID_VALUE, "size is not positive");
  ctx.draw_state.point_size = size;
}

void LineWidth(Context& ctx, GLfloat width) {
  if (!(width > 0.f)) return ctx.record_error(GL_INVALID_VALUE, "width is not positive");
  ctx.draw_state.line_width = width;
}

void ShadeModel(Context& ctx, GLenum mode) {
  if (mode != GL_FLAT && mode != GL_SMOOTH)
    return ctx.record_error(GL_INVALID_ENUM, "mode is not GL_FLAT or GL_SMOOTH");
  ctx.shade_model = mode;
  ctx.draw_state.flat_shading = mode == GL_FLAT;
}

void Hint(Context& ctx, GLenum target, GLenum mode) {
  if (mode != GL_FASTEST && mode != GL_NICEST && mode != GL_DONT_CARE)
    return ctx.record_error(GL_INVALID_ENUM, "mode is not GL_FASTEST, GL_NICEST or GL_DONT_CARE");
  switch (target) {
    case GL_PERSPECTIVE_CORRECTION_HINT: ctx.hint_perspective = mode; break;
    case GL_POINT_SMOOTH_HINT: ctx.hint_point = mode; break;
    case GL_LINE_SMOOTH_HINT: ctx.hint_line = mode; break;
    case GL_POLYGON_SMOOTH_HINT: ctx.hint_polygon = mode; break;
    case GL_FOG_HINT: ctx.hint_fog = mode; break;
    case GL_GENERATE_MIPMAP_HINT: ctx.hint_generate_mipmap = mode; break;
    case GL_TEXTURE_COMPRESSION_HINT: ctx.hint_texture_compression = mode; break;
    case GL_FRAGMENT_SHADER_DERIVATIVE_HINT: ctx.programs.derivative_hint = mode; break;  // GL 2.0
    default: ctx.record_error(GL_INVALID_ENUM, "target is not a hint");
  }
}

}  // namespace pineda::gl
