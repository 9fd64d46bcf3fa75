#include "state/pixels/pixel_unpack.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include "state/pixels/pixel_transfer.h"
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

}  // namespace

size_t client_image_size(const PixelStore& store, int width, int height, GLenum format, GLenum type) {
  if (width <= 0 || height <= 0) return 0;
  if (type == GL_BITMAP) return BitmapLayout(store, width).size(height);
  const ImageLayout layout = image_layout(store, width, format, type);
  return layout.end(height) + layout.pixel_bytes * size_t(width);
}

ClientImage::ClientImage(const PixelStore& store, int width, GLenum format, GLenum type, const void* pixels)
    : format_(format),
      type_(type),
      data_(static_cast<const uint8_t*>(pixels)),
      layout_(image_layout(store, width, format, type)),
      bits_(store, width),
      swap_(store.swap_bytes) {}

const uint8_t* ClientImage::pixel(int i, int64_t j, uint8_t* scratch) const {
  const uint8_t* p = data_ + layout_.offset + layout_.row_stride * size_t(j) + layout_.pixel_bytes * size_t(i);
  if (!swap_ || layout_.pixel_bytes > 16) return p;
  std::memcpy(scratch, p, layout_.pixel_bytes);
  swap_pixel_bytes(scratch, format_, type_);
  return scratch;
}

const uint8_t* ClientImage::row(int64_t j) const { return data_ + layout_.offset + layout_.row_stride * size_t(j); }

int64_t ClientImage::index(int i, int64_t j) const {
  if (type_ == GL_BITMAP) return bits_.bit(data_, i, j);
  uint8_t scratch[16];
  return load_index(pixel(i, j, scratch), type_);
}

ColorImageReader::ColorImageReader(const Context& ctx, int width, GLenum format, GLenum type, const void* pixels)
    : ctx_(ctx),
      width_(width),
      format_(format),
      type_(type),
      image_(ctx.unpack, width, format, type, pixels),
      transfer_(!color_transfer_is_identity(ctx.pixel_mode)),
      rgba8_(rgba8_source(format, type, ctx.unpack.swap_bytes)) {}

void ColorImageReader::read(int i, int64_t j, float rgba[4]) const {
  if (format_ == GL_COLOR_INDEX) return index_to_rgba(ctx_.pixel_mode, ctx_.pixel_maps, image_.index(i, j), rgba);
  uint8_t scratch[16];
  load_color(image_.pixel(i, j, scratch), format_, type_, rgba);
  if (transfer_) transfer_color(ctx_.pixel_mode, ctx_.pixel_maps, rgba);
}

void ColorImageReader::read_row(int64_t j, int first, int count, float* out) const {
  const size_t pixel_bytes = size_t(color_format_components(format_)) * size_t(pixel_type_size(type_));
  if (format_ == GL_COLOR_INDEX || ctx_.unpack.swap_bytes ||
      !load_color_row(image_.row(j) + size_t(first) * pixel_bytes, format_, type_, count, out)) {
    for (int i = 0; i < count; ++i) read(first + i, j, out + 4 * size_t(i));
    return;
  }
  if (transfer_)
    for (int i = 0; i < count; ++i) transfer_color(ctx_.pixel_mode, ctx_.pixel_maps, out + 4 * size_t(i));
}

bool ColorImageReader::rgba8_texels(int64_t j, int first, int count, uint32_t* out) const {
  if (transfer_ || !rgba8_.bytes) return false;
  rgba8_row_texels(rgba8_, image_.row(j) + static_cast<size_t>(first) * static_cast<size_t>(rgba8_.bytes), count, out);
  return true;
}

const uint32_t* ColorImageReader::rgba8_row_words(int64_t j, uint32_t* scratch) const {
  const uint8_t* row = image_.row(j);
  if (std::endian::native == std::endian::little && rgba8_.bytes == 4 && !rgba8_.reversed && !rgba8_.blue_first &&
      reinterpret_cast<uintptr_t>(row) % alignof(uint32_t) == 0)
    return reinterpret_cast<const uint32_t*>(row);
  rgba8_row_texels(rgba8_, row, width_, scratch);
  return scratch;
}

std::vector<double> unpack_depth_image(const Context& ctx, int width, int height, GLenum type, const void* pixels) {
  std::vector<double> out(size_t(width) * size_t(height));
  const ClientImage image(ctx.unpack, width, GL_DEPTH_COMPONENT, type, pixels);
  std::vector<float> row(ctx.unpack.swap_bytes ? 0 : 4 * size_t(width));
  for (int j = 0; j < height; ++j) {
    // A row at a time where the type is an unpacked one in the machine's byte order.
    if (!row.empty() && load_color_row(image.row(j), GL_RED, type, width, row.data())) {
      for (int i = 0; i < width; ++i) out[size_t(j) * width + i] = transfer_depth(ctx.pixel_mode, row[4 * size_t(i)]);
      continue;
    }
    for (int i = 0; i < width; ++i) {
      uint8_t scratch[16];
      float rgba[4];
      load_color(image.pixel(i, j, scratch), GL_RED, type, rgba);
      out[size_t(j) * width + i] = transfer_depth(ctx.pixel_mode, rgba[0]);
    }
  }
  return out;
}

std::vector<int64_t> unpack_stencil_image(const Context& ctx, int width, int height, GLenum type, const void* pixels) {
  std::vector<int64_t> out(size_t(width) * size_t(height));
  const ClientImage image(ctx.unpack, width, GL_STENCIL_INDEX, type, pixels);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i)
      out[size_t(j) * width + i] = transfer_stencil(ctx.pixel_mode, ctx.pixel_maps, image.index(i, j));
  return out;
}

}  // namespace pineda
