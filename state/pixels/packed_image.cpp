#include "state/pixels/packed_image.h"

#include <cstring>
#include <new>

#include "state/pixels/bitmap_layout.h"
#include "state/pixels/pixel_format.h"

namespace pineda {

std::vector<uint8_t> pack_client_image(const PixelStore& store, int width, int height, int depth, bool volume,
                                       GLenum format, GLenum type, const void* pixels) {
  // A 3D bitmap is copied as one tall image (IMAGE_HEIGHT and SKIP_IMAGES are not applied to it).
  if (type == GL_BITMAP) return tight_bitmap_copy(store, width, height * depth, pixels);
  const ImageLayout layout = image_layout(store, width, format, type);
  const size_t row = layout.pixel_bytes * size_t(width);
  const size_t image_rows = store.image_height > 0 ? size_t(store.image_height) : size_t(height);
  const size_t image_stride = layout.row_stride * image_rows;
  size_t bytes = 0;  // more than the address space when it overflows: no such copy can be made
  if (__builtin_mul_overflow(row, size_t(height) * size_t(depth), &bytes)) throw std::bad_alloc();
  std::vector<uint8_t> out(bytes);
  const auto* src = static_cast<const uint8_t*>(pixels) + layout.offset +
                    (volume ? size_t(store.skip_images) * image_stride : 0);
  for (int z = 0; z < depth; ++z)
    for (int y = 0; y < height; ++y)
      std::memcpy(out.data() + row * (size_t(z) * size_t(height) + size_t(y)),
                  src + image_stride * size_t(z) + layout.row_stride * size_t(y), row);
  if (store.swap_bytes)
    for (size_t at = 0; at < out.size(); at += layout.pixel_bytes) swap_pixel_bytes(out.data() + at, format, type);
  return out;
}

}  // namespace pineda
