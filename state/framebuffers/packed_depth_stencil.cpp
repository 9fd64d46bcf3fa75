#include "state/framebuffers/packed_depth_stencil.h"

#include <cstring>

#include "state/context.h"
#include "state/pixel_transfer.h"

namespace pineda {

bool packed_depth_stencil_pixels(GLenum format, GLenum type, GlError& error) {
  if (type == GL_UNSIGNED_INT_24_8) {
    error = format == GL_DEPTH_STENCIL
                ? GlError{}
                : GlError{GL_INVALID_OPERATION, "type GL_UNSIGNED_INT_24_8 takes format GL_DEPTH_STENCIL only"};
    return true;
  }
  error = {GL_INVALID_ENUM, "format GL_DEPTH_STENCIL takes type GL_UNSIGNED_INT_24_8 only"};
  return format == GL_DEPTH_STENCIL;
}

ImageLayout packed_depth_stencil_layout(const PixelStore& store, int width) {
  return image_layout(store, width, GL_RED, GL_UNSIGNED_INT);  // one 4-byte element a pixel
}

void unpack_depth_stencil_image(const Context& ctx, int width, int height, const void* pixels,
                                std::vector<double>& depth, std::vector<int64_t>& stencil) {
  const ImageLayout layout = packed_depth_stencil_layout(ctx.unpack, width);
  const auto* base = static_cast<const uint8_t*>(pixels) + layout.offset;
  const size_t n = size_t(width) * size_t(height);
  depth.assign(n, 0.0);
  stencil.assign(n, 0);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      uint8_t bytes[4];
      std::memcpy(bytes, base + layout.row_stride * size_t(j) + 4 * size_t(i), 4);
      if (ctx.unpack.swap_bytes) swap_component_bytes(bytes, 1, 4);
      uint32_t v;
      std::memcpy(&v, bytes, 4);
      const size_t k = size_t(j) * width + i;
      depth[k] = transfer_depth(ctx.pixel_mode, (v >> 8) / 16777215.0);
      stencil[k] = transfer_stencil(ctx.pixel_mode, ctx.pixel_maps, v & 0xffu);
    }
}

}  // namespace pineda
