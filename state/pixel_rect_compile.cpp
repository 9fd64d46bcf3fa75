// glDrawPixels and glBitmap in display lists: the client image is copied when the list is
// compiled (GL 1.5 spec 5.4), together with the unpack state that describes it.
#include <cstring>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/pixel_unpack.h"

namespace pineda::gl {
namespace {

std::vector<uint8_t> copy_image(const Context& ctx, GLsizei width, GLsizei height, GLenum format, GLenum type,
                                const void* pixels) {
  std::vector<uint8_t> out;
  if (!pixels) return out;
  const auto* bytes = static_cast<const uint8_t*>(pixels);
  out.assign(bytes, bytes + client_image_size(ctx.unpack, width, height, format, type));
  return out;
}

// Runs `call` with the unpack state the image was copied under.
template <typename Call>
void with_unpack(Context& c, const PixelStore& store, Call call) {
  const PixelStore saved = c.unpack;
  c.unpack = store;
  call();
  c.unpack = saved;
}

}  // namespace

void compile_DrawPixels(Context& ctx, GLsizei width, GLsizei height, GLenum format, GLenum type, const void* pixels) {
  // An invalid format or type copies nothing; the call records its error when the list runs.
  const bool known_type = type == GL_BITMAP || client_image_size(ctx.unpack, 1, 1, format, type) > 0;
  auto image = known_type ? copy_image(ctx, width, height, format, type, pixels) : std::vector<uint8_t>{};
  ctx.record_list_command([=, store = ctx.unpack, image = std::move(image)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION);
    // Without a copy (no pixels, or an invalid call) only the error checks run.
    const void* data = image.empty() ? nullptr : image.data();
    with_unpack(c, store, [&] { DrawPixels(c, width, height, format, type, data); });
  });
}

void compile_Bitmap(Context& ctx, GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove,
                    GLfloat ymove, const GLubyte* bitmap) {
  auto image = copy_image(ctx, width, height, GL_COLOR_INDEX, GL_BITMAP, bitmap);
  ctx.record_list_command([=, store = ctx.unpack, image = std::move(image)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION);
    with_unpack(c, store, [&] { Bitmap(c, width, height, xorig, yorig, xmove, ymove, image.empty() ? nullptr : image.data()); });
  });
}

}  // namespace pineda::gl
