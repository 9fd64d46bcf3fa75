#include "state/buffers/pixel_buffer.h"

#include <cstdint>

#include "state/pixels/bitmap_layout.h"
#include "state/framebuffers/packed_depth_stencil.h"
#include "state/pixels/pixel_format.h"

namespace pineda {
namespace {

bool buffer_pixels(Context& ctx, const BufferObject& buffer, const void* offset, size_t bytes, uint8_t*& out) {
  if (buffer.mapped) {
    ctx.record_error(GL_INVALID_OPERATION, "the pixel buffer object is mapped");
    return false;
  }
  out = nullptr;
  if (bytes == 0) return true;
  const uint8_t* data = buffer_range(buffer, reinterpret_cast<uintptr_t>(offset), bytes);
  if (!data) {
    ctx.record_error(GL_INVALID_OPERATION, "the pixels reach past the end of the pixel buffer object");
    return false;
  }
  out = const_cast<uint8_t*>(data);
  return true;
}

}  // namespace

size_t client_image_extent(const PixelStore& store, int width, int height, int depth, bool volume, GLenum format,
                           GLenum type) {
  if (width <= 0 || height <= 0 || depth <= 0) return 0;
  using Wide = unsigned __int128;  // no product of GLsizei-range sizes overflows it
  if (type == GL_BITMAP) {
    const int64_t rows = int64_t(height) * depth;
    return rows > INT32_MAX ? SIZE_MAX : BitmapLayout(store, width).size(int(rows));
  }
  packed_depth_stencil_as_plain(format, type);
  const ImageLayout layout = image_layout(store, width, format, type);
  Wide rows_before = Wide(height - 1);
  if (volume) {
    const Wide image_rows = store.image_height > 0 ? Wide(store.image_height) : Wide(height);
    rows_before += (Wide(store.skip_images > 0 ? store.skip_images : 0) + Wide(depth - 1)) * image_rows;
  }
  const Wide end = Wide(layout.offset) + Wide(layout.row_stride) * rows_before + Wide(layout.pixel_bytes) * Wide(width);
  return end > Wide(SIZE_MAX) ? SIZE_MAX : size_t(end);
}

bool unpack_pixels(Context& ctx, const void*& pixels, size_t bytes) {
  if (!ctx.unpack.buffer) return true;
  uint8_t* data = nullptr;
  if (!buffer_pixels(ctx, *ctx.unpack.buffer, pixels, bytes, data)) return false;
  pixels = data;
  return true;
}

bool pack_pixels(Context& ctx, void*& pixels, size_t bytes, size_t client_bytes) {
  if (!ctx.pack.buffer) {
    if (bytes <= client_bytes) return true;
    ctx.record_error(GL_INVALID_OPERATION, "the data does not fit in bufSize bytes");
    return false;
  }
  uint8_t* data = nullptr;
  if (!buffer_pixels(ctx, *ctx.pack.buffer, pixels, bytes, data)) return false;
  pixels = data;
  return true;
}

}  // namespace pineda
