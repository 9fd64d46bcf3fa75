// glDrawPixels and glBitmap in display lists: the pixels the call reads are copied when the
// list is compiled (GL 1.5 spec 5.4), packed, and replayed under the unpack state that reads
// a packed image. A call that reads no pixels copies none; the list runs its checks.
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/framebuffers/packed_depth_stencil.h"
#include "state/pixels/packed_image.h"
#include "state/buffers/pixel_buffer.h"
#include "state/pixels/pixel_format.h"

namespace pineda::gl {

void compile_DrawPixels(Context& ctx, GLsizei width, GLsizei height, GLenum format, GLenum type, const void* pixels) {
  // Packed DEPTH_STENCIL pixels are laid out as one- or two-component UNSIGNED_INT ones.
  GlError packed_error;
  const bool packed_ds = packed_depth_stencil_pixels(format, type, packed_error) && packed_error == GL_NO_ERROR;
  GLenum plain_format = format, plain_type = type;
  packed_depth_stencil_as_plain(plain_format, plain_type);
  const bool reads = width > 0 && height > 0 &&
                     (packed_ds || pixel_rect_format_type_error(format, type) == GL_NO_ERROR) &&
                     unpack_pixels(ctx, pixels, client_image_extent(ctx.unpack, width, height, 1, false, format, type)) &&
                     pixels;
  auto image = reads ? pack_client_image(ctx.unpack, width, height, 1, false, plain_format, plain_type, pixels)
                     : std::vector<uint8_t>{};
  ctx.record_list_command([=, image = std::move(image)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    const void* data = image.empty() ? nullptr : image.data();
    with_packed_unpack(c, [&] { DrawPixels(c, width, height, format, type, data); });
  });
}

void compile_Bitmap(Context& ctx, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove,
                    GLfloat ymove, const GLubyte* bitmap) {
  const void* data = bitmap;
  const bool reads =
      width > 0 && height > 0 &&
      unpack_pixels(ctx, data, client_image_extent(ctx.unpack, width, height, 1, false, GL_COLOR_INDEX, GL_BITMAP)) &&
      data;
  auto image = reads ? pack_client_image(ctx.unpack, width, height, 1, false, GL_COLOR_INDEX, GL_BITMAP, data)
                     : std::vector<uint8_t>{};
  ctx.record_list_command([=, image = std::move(image)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    const GLubyte* data = image.empty() ? nullptr : image.data();
    with_packed_unpack(c, [&] { Bitmap(c, width, height, xorig, yorig, xmove, ymove, data); });
  });
}

}  // namespace pineda::gl
