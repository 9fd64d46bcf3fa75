#include "state/framebuffers/packed_depth_stencil.h"

#include <bit>
#include <cstring>

#include "state/context.h"
#include "state/pixels/pixel_transfer.h"

namespace pineda {

bool packed_depth_stencil_pixels(GLenum format, GLenum type, GlError& error) {
  if (type == GL_UNSIGNED_INT_24_8 || type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV) {
    error = format == GL_DEPTH_STENCIL
                ? GlError{}
                : GlError{GL_INVALID_OPERATION, "a packed depth-stencil type takes format GL_DEPTH_STENCIL only"};
    return true;
  }
  error = {GL_INVALID_ENUM,
           "format GL_DEPTH_STENCIL takes type GL_UNSIGNED_INT_24_8 or GL_FLOAT_32_UNSIGNED_INT_24_8_REV only"};
  return format == GL_DEPTH_STENCIL;
}

void packed_depth_stencil_as_plain(GLenum& format, GLenum& type) {
  if (format != GL_DEPTH_STENCIL) return;
  if (type == GL_UNSIGNED_INT_24_8) format = GL_RED, type = GL_UNSIGNED_INT;
  if (type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV) format = GL_LUMINANCE_ALPHA, type = GL_UNSIGNED_INT;
}

ImageLayout packed_depth_stencil_layout(const PixelStore& store, int width, GLenum type) {
  GLenum format = GL_DEPTH_STENCIL;
  packed_depth_stencil_as_plain(format, type);
  return image_layout(store, width, format, type);
}

void store_depth_stencil(double depth, uint32_t stencil, GLenum type, bool swap_bytes, uint8_t* dst) {
  if (type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV) {
    const uint32_t words[2] = {std::bit_cast<uint32_t>(static_cast<float>(depth)), stencil & 0xffu};
    std::memcpy(dst, words, 8);
    if (swap_bytes) swap_component_bytes(dst, 2, 4);
    return;
  }
  const uint32_t v = pack_depth_stencil(depth, stencil);
  std::memcpy(dst, &v, 4);
  if (swap_bytes) swap_component_bytes(dst, 1, 4);
}

void unpack_depth_stencil_image(const Context& ctx, int width, int height, GLenum type, const void* pixels,
                                std::vector<double>& depth, std::vector<int64_t>& stencil) {
  const ImageLayout layout = packed_depth_stencil_layout(ctx.unpack, width, type);
  const bool two_words = type == GL_FLOAT_32_UNSIGNED_INT_24_8_REV;
  const auto* base = static_cast<const uint8_t*>(pixels) + layout.offset;
  const size_t n = size_t(width) * size_t(height);
  depth.assign(n, 0.0);
  stencil.assign(n, 0);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      uint8_t bytes[8];
      std::memcpy(bytes, base + layout.row_stride * size_t(j) + layout.pixel_bytes * size_t(i), layout.pixel_bytes);
      if (ctx.unpack.swap_bytes) swap_component_bytes(bytes, two_words ? 2 : 1, 4);
      uint32_t v[2];
      std::memcpy(v, bytes, layout.pixel_bytes);
      const size_t k = size_t(j) * width + i;
      const double z = two_words ? double(std::bit_cast<float>(v[0])) : (v[0] >> 8) / 16777215.0;
      depth[k] = transfer_depth(ctx.pixel_mode, z == z ? z : 0.0);  // NaN as 0
      stencil[k] = transfer_stencil(ctx.pixel_mode, ctx.pixel_maps, (two_words ? v[1] : v[0]) & 0xffu);
    }
}

}  // namespace pineda
