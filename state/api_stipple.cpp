// glLineStipple, glPolygonStipple, glGetPolygonStipple.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/buffers/pixel_buffer.h"
#include "state/stipple_image.h"

namespace pineda::gl {

void LineStipple(Context& ctx, GLint factor, GLushort pattern) {
  raster::LineStipple& l = ctx.draw_state.line_stipple;
  l.factor = std::clamp(factor, 1, 256);
  l.pattern = pattern;
}

namespace {

size_t stipple_extent(const PixelStore& store) {
  return client_image_extent(store, 32, 32, 1, false, GL_COLOR_INDEX, GL_BITMAP);
}

// `client_bytes`: how much client memory `mask` holds, when no pack buffer is bound.
void get_stipple(Context& ctx, GLubyte* mask, size_t client_bytes) {
  void* data = mask;
  if (!pack_pixels(ctx, data, stipple_extent(ctx.pack), client_bytes) || !data) return;
  pack_stipple(ctx.pack, ctx.draw_state.polygon_stipple.rows, static_cast<GLubyte*>(data));
}

}  // namespace

void PolygonStipple(Context& ctx, const GLubyte* mask) {
  const void* data = mask;
  if (!unpack_pixels(ctx, data, stipple_extent(ctx.unpack)) || !data) return;
  ctx.draw_state.polygon_stipple.rows = unpack_stipple(ctx.unpack, static_cast<const GLubyte*>(data));
}

void GetPolygonStipple(Context& ctx, GLubyte* mask) { get_stipple(ctx, mask, SIZE_MAX); }

void GetnPolygonStippleARB(Context& ctx, GLsizei buf_size, GLubyte* pattern) {
  get_stipple(ctx, pattern, client_buffer_bytes(buf_size));
}

// The image is read at compile time, under the unpack state of that time (GL 1.5 section 5.4),
// from the pixel unpack buffer when one is bound.
void compile_PolygonStipple(Context& ctx, const GLubyte* mask) {
  const void* data = mask;
  if (!unpack_pixels(ctx, data, stipple_extent(ctx.unpack)) || !data) return;
  const StippleRows rows = unpack_stipple(ctx.unpack, static_cast<const GLubyte*>(data));
  ctx.record_list_command([rows](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    c.draw_state.polygon_stipple.rows = rows;
  });
}

}  // namespace pineda::gl
