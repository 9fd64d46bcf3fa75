#include "state/pixel_unpack.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "state/pixel_format.h"
#include "state/pixel_transfer.h"
#include "state/unaligned.h"

namespace pineda {
namespace {

// An index component as its integer value (indices are not normalized).
int64_t load_index(const uint8_t* src, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return load_unaligned<GLubyte>(src);
    case GL_BYTE: return load_unaligned<GLbyte>(src);
    case GL_UNSIGNED_SHORT: return load_unaligned<GLushort>(src);
    case GL_SHORT: return load_unaligned<GLshort>(src);
    case GL_UNSIGNED_INT: return load_unaligned<GLuint>(src);
    case GL_INT: return load_unaligned<GLint>(src);
    case GL_FLOAT: {
      const float f = load_unaligned<GLfloat>(src);
      return std::isfinite(f) ? static_cast<int64_t>(std::clamp(f, -2147483648.f, 2147483647.f)) : 0;
    }
    default: return 0;
  }
}

// Calls visit(i, j, bytes) for each pixel of a non-bitmap image; `bytes` already has its
// component bytes swapped when UNPACK_SWAP_BYTES is on.
template <typename Visit>
void for_each_pixel(const PixelStore& store, int width, int height, GLenum format, GLenum type, const void* pixels,
                    Visit visit) {
  const ImageLayout layout = image_layout(store, width, format, type);
  const bool color = color_format_components(format) > 0;
  const auto* base = static_cast<const uint8_t*>(pixels) + layout.offset;
  uint8_t swapped[64];
  for (int j = 0; j < height; ++j) {
    const uint8_t* row = base + layout.row_stride * size_t(j);
    for (int i = 0; i < width; ++i) {
      const uint8_t* p = row + layout.pixel_bytes * size_t(i);
      if (store.swap_bytes && layout.pixel_bytes <= sizeof swapped) {
        std::memcpy(swapped, p, layout.pixel_bytes);
        if (color) swap_pixel_bytes(swapped, format, type);
        else swap_component_bytes(swapped, 1, pixel_type_size(type));
        p = swapped;
      }
      visit(i, j, p);
    }
  }
}

std::vector<int64_t> unpack_indices(const PixelStore& store, int width, int height, GLenum format, GLenum type,
                                    const void* pixels) {
  std::vector<int64_t> out(size_t(width) * size_t(height));
  if (type == GL_BITMAP) {
    const BitmapLayout bits(store, width);
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) out[size_t(j) * width + i] = bits.bit(static_cast<const uint8_t*>(pixels), i, j);
    return out;
  }
  for_each_pixel(store, width, height, format, type, pixels,
                 [&](int i, int j, const uint8_t* p) { out[size_t(j) * width + i] = load_index(p, type); });
  return out;
}

}  // namespace

size_t client_image_size(const PixelStore& store, int width, int height, GLenum format, GLenum type) {
  if (width <= 0 || height <= 0) return 0;
  if (type == GL_BITMAP) return BitmapLayout(store, width).size(height);
  const ImageLayout layout = image_layout(store, width, format, type);
  return layout.end(height) + layout.pixel_bytes * size_t(width);
}

std::vector<float> unpack_color_image(const Context& ctx, int width, int height, GLenum format, GLenum type,
                                      const void* pixels) {
  std::vector<float> out(size_t(width) * size_t(height) * 4);
  if (format == GL_COLOR_INDEX) {
    const std::vector<int64_t> indices = unpack_indices(ctx.unpack, width, height, format, type, pixels);
    for (size_t k = 0; k < indices.size(); ++k) index_to_rgba(ctx.pixel_mode, ctx.pixel_maps, indices[k], &out[4 * k]);
    return out;
  }
  const bool identity = color_transfer_is_identity(ctx.pixel_mode);
  for_each_pixel(ctx.unpack, width, height, format, type, pixels, [&](int i, int j, const uint8_t* p) {
    float* rgba = &out[(size_t(j) * width + i) * 4];
    load_color(p, format, type, rgba);
    if (!identity) transfer_color(ctx.pixel_mode, ctx.pixel_maps, rgba);
  });
  return out;
}

std::vector<double> unpack_depth_image(const Context& ctx, int width, int height, GLenum type, const void* pixels) {
  std::vector<double> out(size_t(width) * size_t(height));
  for_each_pixel(ctx.unpack, width, height, GL_DEPTH_COMPONENT, type, pixels, [&](int i, int j, const uint8_t* p) {
    float rgba[4];
    load_color(p, GL_RED, type, rgba);
    out[size_t(j) * width + i] = transfer_depth(ctx.pixel_mode, rgba[0]);
  });
  return out;
}

std::vector<int64_t> unpack_stencil_image(const Context& ctx, int width, int height, GLenum type, const void* pixels) {
  std::vector<int64_t> out = unpack_indices(ctx.unpack, width, height, GL_STENCIL_INDEX, type, pixels);
  for (int64_t& s : out) s = transfer_stencil(ctx.pixel_mode, ctx.pixel_maps, s);
  return out;
}

}  // namespace pineda
