#include "state/pixels/pixel_format.h"

#include "state/framebuffers/packed_depth_stencil.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "state/context.h"
#include "state/pixels/packed_pixel.h"
#include "state/unaligned.h"

namespace pineda {
namespace {

// GL's float -> normalized integer conversions, rounding to nearest; in double precision so
// that 32-bit types (depth read as GL_UNSIGNED_INT) keep every bit.
void store_component(double c, GLenum type, uint8_t* dst) {
  switch (type) {
    case GL_UNSIGNED_BYTE: store_unaligned<GLubyte>(dst, GLubyte(std::lround(c * 255.0))); break;
    case GL_BYTE: store_unaligned<GLbyte>(dst, GLbyte(std::lround(c * 127.0))); break;
    case GL_UNSIGNED_SHORT: store_unaligned<GLushort>(dst, GLushort(std::lround(c * 65535.0))); break;
    case GL_SHORT: store_unaligned<GLshort>(dst, GLshort(std::lround(c * 32767.0))); break;
    case GL_UNSIGNED_INT: store_unaligned<GLuint>(dst, GLuint(std::llround(c * 4294967295.0))); break;
    case GL_INT: store_unaligned<GLint>(dst, GLint(std::llround(c * 2147483647.0))); break;
    case GL_FLOAT: store_unaligned<GLfloat>(dst, GLfloat(c)); break;
  }
}

// A component of type T as a float (GL 2.1 table 2.9; the signed types clamped to -1).
float component_value(GLubyte v) { return v / 255.f; }
float component_value(GLbyte v) { return std::max(v / 127.f, -1.f); }
float component_value(GLushort v) { return v / 65535.f; }
float component_value(GLshort v) { return std::max(v / 32767.f, -1.f); }
float component_value(GLuint v) { return float(v / 4294967295.0); }
float component_value(GLint v) { return float(std::max(v / 2147483647.0, -1.0)); }
float component_value(GLfloat v) { return v; }

float load_component(const uint8_t* src, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return component_value(load_unaligned<GLubyte>(src));
    case GL_BYTE: return component_value(load_unaligned<GLbyte>(src));
    case GL_UNSIGNED_SHORT: return component_value(load_unaligned<GLushort>(src));
    case GL_SHORT: return component_value(load_unaligned<GLshort>(src));
    case GL_UNSIGNED_INT: return component_value(load_unaligned<GLuint>(src));
    case GL_INT: return component_value(load_unaligned<GLint>(src));
    case GL_FLOAT: return component_value(load_unaligned<GLfloat>(src));
    default: return 0.f;
  }
}

// load_color over a row of pixels of an unpacked type T, the format's channels decoded once.
template <typename T>
void load_color_row(const uint8_t* src, GLenum format, int count, float* out) {
  if (format == GL_RGBA) {  // component for component (a loop that vectorizes)
    if constexpr (std::is_same_v<T, GLfloat>) {  // component_value returns a float as it is
      std::memcpy(out, src, 4 * sizeof(float) * static_cast<size_t>(count));
      return;
    }
    for (size_t i = 0; i < 4 * static_cast<size_t>(count); ++i) out[i] = component_value(load_unaligned<T>(src + i * sizeof(T)));
    return;
  }
  int channels[4];
  const int n = color_format_components(format);
  for (int c = 0; c < n; ++c) channels[c] = channel_of(format, c);
  for (int i = 0; i < count; ++i, src += n * sizeof(T), out += 4) {
    out[0] = out[1] = out[2] = 0.f;
    out[3] = 1.f;
    for (int c = 0; c < n; ++c) {
      const float v = component_value(load_unaligned<T>(src + c * sizeof(T)));
      if (channels[c] < 0)
        out[0] = out[1] = out[2] = v;
      else
        out[channels[c]] = v;
    }
  }
}

}  // namespace

int channel_of(GLenum format, int component) {
  switch (format) {
    case GL_RED: return 0;
    case GL_GREEN: return 1;
    case GL_BLUE: return 2;
    case GL_ALPHA: return 3;
    case GL_LUMINANCE: return -1;
    case GL_LUMINANCE_ALPHA: return component == 0 ? -1 : 3;
    case GL_BGR: case GL_BGRA: return component < 3 ? 2 - component : 3;
    default: return component;  // RGB, RGBA
  }
}

int color_format_components(GLenum format) {
  switch (format) {
    case GL_RED: case GL_GREEN: case GL_BLUE: case GL_ALPHA: case GL_LUMINANCE: return 1;
    case GL_LUMINANCE_ALPHA: return 2;
    case GL_RGB: case GL_BGR: return 3;
    case GL_RGBA: case GL_BGRA: return 4;
    default: return 0;
  }
}

int pixel_type_size(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    case GL_UNSIGNED_INT: case GL_INT: case GL_FLOAT: return 4;
    default: return 0;
  }
}

bool is_packed_pixel_type(GLenum type) { return packed_layout(type) != nullptr; }

int pixel_element_size(GLenum type) {
  const PackedLayout* packed = packed_layout(type);
  return packed ? packed->bytes : pixel_type_size(type);
}

GlError color_format_type_error(GLenum format, GLenum type) {
  if (color_format_components(format) == 0) return {GL_INVALID_ENUM, "format is not a colour format"};
  if (pixel_element_size(type) == 0) return {GL_INVALID_ENUM, "type is not a pixel type"};
  const PackedLayout* packed = packed_layout(type);
  if (!packed) return GL_NO_ERROR;
  const bool fits = packed->components == 3 ? format == GL_RGB : (format == GL_RGBA || format == GL_BGRA);
  if (!fits) return {GL_INVALID_OPERATION, "type is a packed type whose components format does not have"};
  return GL_NO_ERROR;
}

GlError pixel_rect_format_type_error(GLenum format, GLenum type) {
  if (is_packed_pixel_type(type) && color_format_type_error(format, type) != GL_NO_ERROR)
    return {GL_INVALID_OPERATION, "type is a packed type whose components format does not have"};
  if (color_format_components(format) > 0) return color_format_type_error(format, type);
  const bool index = format == GL_COLOR_INDEX || format == GL_STENCIL_INDEX;
  if (!index && format != GL_DEPTH_COMPONENT) return {GL_INVALID_ENUM, "format is not a pixel format"};
  if (type == GL_BITMAP && !index) return {GL_INVALID_ENUM, "type is GL_BITMAP and format is not an index format"};
  if (type == GL_BITMAP) return GL_NO_ERROR;
  return pixel_element_size(type) == 0 ? GlError{GL_INVALID_ENUM, "type is not a pixel type"} : GlError{};
}

GlError texture_image_format_type_error(GLenum format, GLenum type) {
  if (GlError error; packed_depth_stencil_pixels(format, type, error)) return error;
  if (const GlError error = pixel_rect_format_type_error(format, type); error != GL_NO_ERROR) return error;
  // A pixel format, but no texture format takes stencil indices alone: they never agree (Mesa's
  // INVALID_OPERATION, texture_formats_agree).
  if (format == GL_STENCIL_INDEX) return {GL_INVALID_OPERATION, "no texture format takes GL_STENCIL_INDEX data"};
  return GL_NO_ERROR;
}

// GL 1.1 spec 3.6.4: rows start at multiples of the alignment when elements are smaller.
ImageLayout image_layout(const PixelStore& store, int width, GLenum format, GLenum type) {
  ImageLayout l;
  const int components = std::max(color_format_components(format), 1);
  const size_t size = pixel_element_size(type);
  const PackedLayout* packed = packed_layout(type);
  l.pixel_bytes = packed ? size : components * size;
  const size_t row_pixels = store.row_length > 0 ? size_t(store.row_length) : size_t(std::max(width, 0));
  const size_t row_bytes = row_pixels * l.pixel_bytes;
  const size_t align = size_t(store.alignment);
  l.row_stride = size >= align ? row_bytes : (row_bytes + align - 1) / align * align;
  l.offset = size_t(std::max(store.skip_rows, 0)) * l.row_stride + size_t(std::max(store.skip_pixels, 0)) * l.pixel_bytes;
  return l;
}

void store_color(const double rgba[4], GLenum format, GLenum type, uint8_t* dst) {
  const int n = color_format_components(format);
  if (const PackedLayout* packed = packed_layout(type)) {
    double components[4] = {0, 0, 0, 0};
    for (int c = 0; c < n && c < 4; ++c) components[c] = rgba[channel_of(format, c)];
    return pack_components(components, *packed, dst);
  }
  const int size = pixel_type_size(type);
  for (int c = 0; c < n; ++c) {
    const int ch = channel_of(format, c);
    const double v = ch < 0 ? std::min(rgba[0] + rgba[1] + rgba[2], 1.0) : rgba[ch];
    store_component(v, type, dst + c * size);
  }
}

void load_color(const uint8_t* src, GLenum format, GLenum type, float rgba[4]) {
  rgba[0] = rgba[1] = rgba[2] = 0.f;
  rgba[3] = 1.f;
  const int n = color_format_components(format);
  const int size = pixel_type_size(type);
  float packed_values[4] = {0, 0, 0, 1};
  const PackedLayout* packed = packed_layout(type);
  if (packed) unpack_components(src, *packed, packed_values);
  for (int c = 0; c < n; ++c) {
    const float v = packed ? packed_values[c] : load_component(src + c * size, type);
    const int ch = channel_of(format, c);
    if (ch < 0)
      rgba[0] = rgba[1] = rgba[2] = v;
    else
      rgba[ch] = v;
  }
}

bool load_color_row(const uint8_t* src, GLenum format, GLenum type, int count, float* out) {
  if (color_format_components(format) == 0) return false;
  switch (type) {
    case GL_UNSIGNED_BYTE: load_color_row<GLubyte>(src, format, count, out); return true;
    case GL_BYTE: load_color_row<GLbyte>(src, format, count, out); return true;
    case GL_UNSIGNED_SHORT: load_color_row<GLushort>(src, format, count, out); return true;
    case GL_SHORT: load_color_row<GLshort>(src, format, count, out); return true;
    case GL_UNSIGNED_INT: load_color_row<GLuint>(src, format, count, out); return true;
    case GL_INT: load_color_row<GLint>(src, format, count, out); return true;
    case GL_FLOAT: load_color_row<GLfloat>(src, format, count, out); return true;
    default: return false;
  }
}

void swap_component_bytes(uint8_t* p, int count, int size) {
  if (size < 2) return;
  for (int c = 0; c < count; ++c) std::reverse(p + c * size, p + (c + 1) * size);
}

void swap_pixel_bytes(uint8_t* p, GLenum format, GLenum type) {
  if (const PackedLayout* packed = packed_layout(type)) return swap_component_bytes(p, 1, packed->bytes);
  swap_component_bytes(p, std::max(color_format_components(format), 1), pixel_type_size(type));  // indices, depth: 1
}

void store_depth(double value, GLenum type, uint8_t* dst) { store_component(value, type, dst); }

// GL 1.5 spec table 4.7: an index keeps as many low bits as the type has (7 for the signed ones).
void store_index(int64_t index, GLenum type, uint8_t* dst) {
  switch (type) {
    case GL_UNSIGNED_BYTE: store_unaligned<GLubyte>(dst, GLubyte(index & 0xff)); break;
    case GL_BYTE: store_unaligned<GLbyte>(dst, GLbyte(index & 0x7f)); break;
    case GL_UNSIGNED_SHORT: store_unaligned<GLushort>(dst, GLushort(index & 0xffff)); break;
    case GL_SHORT: store_unaligned<GLshort>(dst, GLshort(index & 0x7fff)); break;
    case GL_UNSIGNED_INT: store_unaligned<GLuint>(dst, GLuint(index & 0xffffffff)); break;
    case GL_INT: store_unaligned<GLint>(dst, GLint(index & 0x7fffffff)); break;
    case GL_FLOAT: store_unaligned<GLfloat>(dst, GLfloat(index)); break;
  }
}

}  // namespace pineda
