// glPixelTransfer, glPixelZoom, glPixelMap and glGetPixelMap (GL 1.5 spec 3.6.3, 6.1.3).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/pixels/packed_image.h"
#include "state/buffers/pixel_buffer.h"
#include "state/unaligned.h"

namespace pineda::gl {
namespace {

float* transfer_float(PixelMode& m, GLenum pname) {
  switch (pname) {
    case GL_RED_SCALE: return &m.scale[0];
    case GL_GREEN_SCALE: return &m.scale[1];
    case GL_BLUE_SCALE: return &m.scale[2];
    case GL_ALPHA_SCALE: return &m.scale[3];
    case GL_RED_BIAS: return &m.bias[0];
    case GL_GREEN_BIAS: return &m.bias[1];
    case GL_BLUE_BIAS: return &m.bias[2];
    case GL_ALPHA_BIAS: return &m.bias[3];
    case GL_DEPTH_SCALE: return &m.depth_scale;
    case GL_DEPTH_BIAS: return &m.depth_bias;
    default: return nullptr;
  }
}

void set_transfer(Context& ctx, GLenum pname, double value) {
  PixelMode& m = ctx.pixel_mode;
  if (float* f = transfer_float(m, pname)) {
    *f = static_cast<float>(value);
    return;
  }
  switch (pname) {
    case GL_MAP_COLOR: m.map_color = value != 0.0; return;
    case GL_MAP_STENCIL: m.map_stencil = value != 0.0; return;
    case GL_INDEX_SHIFT: m.index_shift = round_int_param(value); return;
    case GL_INDEX_OFFSET: m.index_offset = round_int_param(value); return;
    default: ctx.record_error(GL_INVALID_ENUM, "pname is not a pixel transfer parameter");
  }
}

bool is_pixel_map(GLenum map) { return map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_A_TO_A; }
// I_TO_I and S_TO_S hold indices; the others hold colour components.
bool is_index_map(GLenum map) { return map == GL_PIXEL_MAP_I_TO_I || map == GL_PIXEL_MAP_S_TO_S; }
// Maps indexed by a colour index or stencil index need a power-of-two size.
bool needs_power_of_two(GLenum map) { return map >= GL_PIXEL_MAP_I_TO_I && map <= GL_PIXEL_MAP_I_TO_A; }

// `normalize_max`: the integer type's maximum (colour maps read unsigned integers as [0, 1]).
GlError pixel_map_error(GLenum map, GLsizei size) {
  if (!is_pixel_map(map)) return {GL_INVALID_ENUM, "map is not a pixel map"};
  if (size < 1 || size > kMaxPixelMapTable)
    return {GL_INVALID_VALUE, "mapsize is less than 1 or above GL_MAX_PIXEL_MAP_TABLE"};
  if (needs_power_of_two(map) && (size & (size - 1)) != 0)
    return {GL_INVALID_VALUE, "mapsize is not a power of two for an index map"};
  return GL_NO_ERROR;
}

// With a pixel unpack buffer bound, `values` is an offset into it (no pixel store mode applies).
template <typename T>
void set_map(Context& ctx, GLenum map, GLsizei size, const T* values, double normalize_max) {
  if (const GlError error = pixel_map_error(map, size); error != GL_NO_ERROR) return ctx.record_error(error);
  const void* data = values;
  if (!unpack_pixels(ctx, data, size_t(size) * sizeof(T)) || !data) return;
  std::vector<float>& table = ctx.pixel_maps[map];
  table.resize(size_t(size));
  for (GLsizei i = 0; i < size; ++i) {
    const double v = double(load_unaligned<T>(static_cast<const uint8_t*>(data) + sizeof(T) * size_t(i)));
    table[i] = is_index_map(map) ? static_cast<float>(v)
                                 : std::clamp(static_cast<float>(v / normalize_max), 0.f, 1.f);
  }
}

// The values are copied at compile time only when the call is valid: `size` may be anything.
template <typename T>
void compile_map(Context& ctx, GLenum map, GLsizei size, const T* values, double normalize_max) {
  const GlError error = pixel_map_error(map, size);
  std::vector<T> copy;
  const void* data = values;
  if (error == GL_NO_ERROR && unpack_pixels(ctx, data, size_t(size) * sizeof(T)) && data) {
    copy.resize(size_t(size));
    std::memcpy(copy.data(), data, size_t(size) * sizeof(T));
  }
  ctx.record_list_command([=, copy = std::move(copy)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    if (error != GL_NO_ERROR) return c.record_error(error);
    with_packed_unpack(c, [&] { set_map(c, map, size, copy.empty() ? nullptr : copy.data(), normalize_max); });
  });
}

// `client_bytes`: how much client memory `values` holds, when no pack buffer is bound.
template <typename T>
void get_map(Context& ctx, GLenum map, T* values, double normalize_max, size_t client_bytes = SIZE_MAX) {
  if (!is_pixel_map(map)) return ctx.record_error(GL_INVALID_ENUM, "map is not a pixel map");
  const std::vector<float>& table = ctx.pixel_maps[map];
  void* data = values;
  if (!pack_pixels(ctx, data, table.size() * sizeof(T), client_bytes) || !data) return;
  for (size_t i = 0; i < table.size(); ++i) {
    double v = table[i];
    if (normalize_max != 1.0 && std::isnan(v)) v = 0.0;  // as an integer NaN reads 0 (converting it is undefined)
    T out;
    if (normalize_max == 1.0) out = static_cast<T>(v);
    else if (is_index_map(map)) out = static_cast<T>(std::clamp(v, 0.0, normalize_max));
    else out = static_cast<T>(std::llround(v * normalize_max));
    std::memcpy(static_cast<uint8_t*>(data) + sizeof(T) * i, &out, sizeof(T));
  }
}

}  // namespace

void PixelTransferf(Context& ctx, GLenum pname, GLfloat param) { set_transfer(ctx, pname, param); }
void PixelTransferi(Context& ctx, GLenum pname, GLint param) { set_transfer(ctx, pname, param); }

void PixelZoom(Context& ctx, GLfloat xfactor, GLfloat yfactor) {
  ctx.pixel_mode.zoom_x = xfactor;
  ctx.pixel_mode.zoom_y = yfactor;
}

void PixelMapfv(Context& ctx, GLenum map, GLsizei mapsize, const GLfloat* values) {
  set_map(ctx, map, mapsize, values, 1.0);
}
void PixelMapuiv(Context& ctx, GLenum map, GLsizei mapsize, const GLuint* values) {
  set_map(ctx, map, mapsize, values, 4294967295.0);
}
void PixelMapusv(Context& ctx, GLenum map, GLsizei mapsize, const GLushort* values) {
  set_map(ctx, map, mapsize, values, 65535.0);
}

void compile_PixelMapfv(Context& ctx, GLenum map, GLsizei mapsize, const GLfloat* values) {
  compile_map(ctx, map, mapsize, values, 1.0);
}
void compile_PixelMapuiv(Context& ctx, GLenum map, GLsizei mapsize, const GLuint* values) {
  compile_map(ctx, map, mapsize, values, 4294967295.0);
}
void compile_PixelMapusv(Context& ctx, GLenum map, GLsizei mapsize, const GLushort* values) {
  compile_map(ctx, map, mapsize, values, 65535.0);
}

void GetPixelMapfv(Context& ctx, GLenum map, GLfloat* values) { get_map(ctx, map, values, 1.0); }
void GetPixelMapuiv(Context& ctx, GLenum map, GLuint* values) { get_map(ctx, map, values, 4294967295.0); }
void GetPixelMapusv(Context& ctx, GLenum map, GLushort* values) { get_map(ctx, map, values, 65535.0); }

void GetnPixelMapfvARB(Context& ctx, GLenum map, GLsizei buf_size, GLfloat* values) {
  get_map(ctx, map, values, 1.0, client_buffer_bytes(buf_size));
}
void GetnPixelMapuivARB(Context& ctx, GLenum map, GLsizei buf_size, GLuint* values) {
  get_map(ctx, map, values, 4294967295.0, client_buffer_bytes(buf_size));
}
void GetnPixelMapusvARB(Context& ctx, GLenum map, GLsizei buf_size, GLushort* values) {
  get_map(ctx, map, values, 65535.0, client_buffer_bytes(buf_size));
}

}  // namespace pineda::gl
