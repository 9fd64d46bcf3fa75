// Client pixel formats: sizes, row layout under PixelStore, and per-pixel conversion
// between the application's format/type and RGBA floats.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>
#include <cstdint>

#include "state/gl_error.h"

namespace pineda {

struct PixelStore;

// Components per pixel of a colour format (RGBA, RGB, BGRA, BGR, RED, GREEN, BLUE, ALPHA,
// LUMINANCE, LUMINANCE_ALPHA), or 0 when `format` is not one.
int color_format_components(GLenum format);
// Which RGBA channel component `component` of colour format `format` holds; -1 for luminance
// (R + G + B on read).
int channel_of(GLenum format, int component);
// Bytes of one component of `type` (the unpacked types), or 0 when it is not one.
int pixel_type_size(GLenum type);
// Whether `type` packs a whole pixel into one byte, short or int (GL 1.2's *_3_3_2 ...
// *_2_10_10_10_REV types).
bool is_packed_pixel_type(GLenum type);
// Bytes of one element: a component of an unpacked type, a pixel of a packed one; 0 when
// `type` is not a colour pixel type. Alignment and byte swapping work on elements.
int pixel_element_size(GLenum type);
// GL_NO_ERROR when colour pixels of format/type can be read or written; GL_INVALID_ENUM for
// an unknown format or type; GL_INVALID_OPERATION for a packed type the format does not fit
// (3-component types need RGB, 4-component ones RGBA or BGRA).
GlError color_format_type_error(GLenum format, GLenum type);
// GL_NO_ERROR when format/type can describe a pixel rectangle of glDrawPixels or glReadPixels:
// the colour formats, COLOR_INDEX and STENCIL_INDEX (also with BITMAP) and DEPTH_COMPONENT.
// GL_INVALID_ENUM for an unknown format or type, or BITMAP with another format;
// GL_INVALID_OPERATION for a packed type the format does not fit, whatever the format (as Mesa).
GlError pixel_rect_format_type_error(GLenum format, GLenum type);
// GL_NO_ERROR when format/type can describe a texture image (GL 1.5 3.8.1): a colour format
// with its types, COLOR_INDEX (BITMAP too) or DEPTH_COMPONENT. Otherwise the error of
// pixel_rect_format_type_error (a packed type the format does not fit is INVALID_OPERATION
// whatever the format, as Mesa), or INVALID_ENUM for stencil data.
GlError texture_image_format_type_error(GLenum format, GLenum type);

// The byte layout of a width x height image in client memory.
struct ImageLayout {
  size_t pixel_bytes = 0;
  size_t row_stride = 0;
  size_t offset = 0;  // of the first pixel, from the skips
  size_t end(int height) const { return height > 0 ? offset + row_stride * size_t(height - 1) : 0; }
};
ImageLayout image_layout(const PixelStore& store, int width, GLenum format, GLenum type);

// One pixel of a colour format, converted from RGBA (already clamped to [0, 1]); packed
// types included.
// Double precision, so that 32-bit integer types receive exact values.
void store_color(const double rgba[4], GLenum format, GLenum type, uint8_t* dst);
// One pixel of a colour format, converted to RGBA with GL's defaults for missing components;
// packed types included.
void load_color(const uint8_t* src, GLenum format, GLenum type, float rgba[4]);
// load_color of `count` pixels from `src` (RGBA per pixel to `out`), for a colour format of an
// unpacked type stored in the machine's byte order; false, with nothing written, for others.
bool load_color_row(const uint8_t* src, GLenum format, GLenum type, int count, float* out);
// Reverses the bytes of each of `count` components of `size` bytes (GL_*_SWAP_BYTES).
void swap_component_bytes(uint8_t* p, int count, int size);
// Reverses the bytes of each element of one pixel of format/type (GL_*_SWAP_BYTES); a format
// that is not a colour one (index, depth) has one component.
void swap_pixel_bytes(uint8_t* p, GLenum format, GLenum type);
// A depth value in [0, 1] as a normalized component of `type`.
void store_depth(double value, GLenum type, uint8_t* dst);
// A colour or stencil index as `type` holds it (its low bits; float as is).
void store_index(int64_t index, GLenum type, uint8_t* dst);

}  // namespace pineda
