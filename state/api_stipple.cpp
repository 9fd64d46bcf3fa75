// glLineStipple, glPolygonStipple, glGetPolygonStipple.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/stipple_image.h"

namespace pineda::gl {

void LineStipple(Context& ctx, GLint factor, GLushort pattern) {
  raster::LineStipple& l = ctx.draw_state.line_stipple;
  l.factor = std::clamp(factor, 1, 256);
  l.pattern = pattern;
}

void PolygonStipple(Context& ctx, const GLubyte* mask) {
  if (!mask) return;
  ctx.draw_state.polygon_stipple.rows = unpack_stipple(ctx.unpack, mask);
}

void GetPolygonStipple(Context& ctx, GLubyte* mask) {
  if (!mask) return;
  pack_stipple(ctx.pack, ctx.draw_state.polygon_stipple.rows, mask);
}

// The image is read at compile time, under the unpack state of that time (GL 1.5 section 5.4).
void compile_PolygonStipple(Context& ctx, const GLubyte* mask) {
  if (!mask) return;
  const StippleRows rows = unpack_stipple(ctx.unpack, mask);
  ctx.record_list_command([rows](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION);
    c.draw_state.polygon_stipple.rows = rows;
  });
}

}  // namespace pineda::gl
