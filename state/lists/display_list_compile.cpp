// The calls that read client memory are compiled by reading it now (GL 1.1 spec 5.4):
// vertex arrays become vertex data in the list, images become tightly packed copies.
#include <algorithm>
#include <optional>

#include "glapi/gl_entry_points.h"
#include "state/buffers/buffer_draw.h"
#include "state/context.h"
#include "state/draw.h"
#include "state/enum_translate.h"
#include "state/pixels/packed_image.h"
#include "state/buffers/pixel_buffer.h"
#include "state/textures/tex_image_checks.h"
#include "state/textures/texture_target.h"
#include "state/vertex_arrays/vertex_fetch.h"
#include "state/vertex_arrays/vertex_fetch_plan.h"

namespace pineda::gl {
namespace {

// Which attributes came from enabled arrays; the others take the current values when the
// list runs.
struct ArraySources {
  bool vertex = false, color = false, normal = false, index = false;
  bool texcoord[raster::kMaxTextureUnits] = {};
};

ArraySources array_sources(const Context& ctx) {
  ArraySources s;
  s.vertex = ctx.vertex_array.active();
  s.color = ctx.color_array.active();
  s.normal = ctx.normal_array.active();
  s.index = ctx.index_array.active();
  for (int u = 0; u < raster::kMaxTextureUnits; ++u)
    s.texcoord[u] = ctx.texture_units[u].texcoord_array.active();
  return s;
}

void merge_current(const Context& ctx, const ArraySources& s, raster::VertexInput& v) {
  if (!s.color) std::copy(ctx.current_color, ctx.current_color + 4, v.color);
  if (!s.normal) std::copy(ctx.current_normal, ctx.current_normal + 3, v.normal);
  for (int u = 0; u < raster::kMaxTextureUnits; ++u)
    if (!s.texcoord[u])
      std::copy(ctx.texture_units[u].current_texcoord, ctx.texture_units[u].current_texcoord + 4, v.texcoord[u]);
  v.edge_flag = ctx.current_edge_flag;
}

// `last_index`: the index array's value for the last vertex, which the draw leaves current.
void record_draw(Context& ctx, GLenum mode, std::vector<raster::VertexInput> vertices, GlError error,
                 std::optional<float> last_index = {}) {
  const ArraySources sources = array_sources(ctx);
  ctx.record_list_command([mode, vertices = std::move(vertices), sources, error, last_index](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    if (error != GL_NO_ERROR) return c.record_error(error);
    if (!sources.vertex || vertices.empty()) return;
    // Copied and merged vertex by vertex, while each is in the cache.
    if (c.fetched.size() < vertices.size()) c.fetched.resize(vertices.size());  // only grows
    for (size_t i = 0; i < vertices.size(); ++i) {
      c.fetched[i] = vertices[i];
      merge_current(c, sources, c.fetched[i]);
    }
    draw_vertices(c, mode, std::span<const raster::VertexInput>(c.fetched.data(), vertices.size()), {});
    if (last_index) c.color_index.current_index = *last_index;
  });
}

GlError mode_error(GLenum mode) {
  raster::Primitive p;
  return to_primitive(mode, p) ? GlError{} : GlError{GL_INVALID_ENUM, "mode is not a primitive type"};
}

// Returns the last element's colour index (see record_draw).
template <typename Index>
std::optional<float> fetch_indexed(const Context& ctx, GLsizei count, const Index* indices,
                                   std::vector<raster::VertexInput>& out) {
  out.resize(count);
  VertexFetchPlan plan;
  plan.build(ctx);
  for (GLsizei i = 0; i < count; ++i) plan.fetch(indices[i], out[i]);
  if (count == 0 || !ctx.index_array.active()) return {};
  return fetch_index(ctx, indices[count - 1]);
}

// A copy of the pixels a texture image call reads (from the pixel unpack buffer when one is
// bound), or empty when it reads none.
std::vector<uint8_t> texture_pixels(Context& ctx, bool reads, GLsizei width, GLsizei height, GLsizei depth,
                                    bool volume, GLenum format, GLenum type, const void* pixels) {
  if (!reads || width == 0 || height == 0 || depth == 0) return {};
  if (!unpack_pixels(ctx, pixels, client_image_extent(ctx.unpack, width, height, depth, volume, format, type)) ||
      !pixels)
    return {};
  return pack_client_image(ctx.unpack, width, height, depth, volume, format, type, pixels);
}

bool is_proxy(GLenum target) {
  ImageTarget t;
  return image_target(target, t) && t.proxy;
}

}  // namespace

void compile_ArrayElement(Context& ctx, GLint i) {
  raster::VertexInput v;
  if (i >= 0) fetch_vertex(ctx, size_t(i), v);
  const ArraySources sources = array_sources(ctx);
  const float index = fetch_index(ctx, i >= 0 ? size_t(i) : 0);
  ctx.record_list_command([i, v, sources, index](Context& c) {
    if (i < 0) return c.record_error(GL_INVALID_VALUE, "i is negative");
    if (sources.index) c.color_index.current_index = index;
    if (sources.color) std::copy(v.color, v.color + 4, c.current_color);
    if (sources.normal) std::copy(v.normal, v.normal + 3, c.current_normal);
    for (int u = 0; u < raster::kMaxTextureUnits; ++u)
      if (sources.texcoord[u]) std::copy(v.texcoord[u], v.texcoord[u] + 4, c.texture_units[u].current_texcoord);
    if (!sources.vertex || !c.in_begin_end) return;
    raster::VertexInput vertex = v;
    merge_current(c, sources, vertex);
    c.immediate.push_back(vertex);
  });
}

void compile_DrawArrays(Context& ctx, GLenum mode, GLint first, GLsizei count) {
  GlError error = mode_error(mode);
  if (error == GL_NO_ERROR && count < 0) error = {GL_INVALID_VALUE, "count is negative"};
  if (error == GL_NO_ERROR && first < 0) error = {GL_INVALID_VALUE, "first is negative"};
  std::vector<raster::VertexInput> vertices;
  if (error == GL_NO_ERROR && array_sources(ctx).vertex) {
    vertices.resize(count);
    VertexFetchPlan plan;
    plan.build(ctx);
    for (GLsizei i = 0; i < count; ++i) plan.fetch(size_t(first) + i, vertices[i]);
  }
  std::optional<float> last_index;
  if (!vertices.empty() && ctx.index_array.active()) last_index = fetch_index(ctx, size_t(first) + count - 1);
  record_draw(ctx, mode, std::move(vertices), error, last_index);
}

void compile_DrawElements(Context& ctx, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  GlError error = mode_error(mode);
  if (error == GL_NO_ERROR && count < 0) error = {GL_INVALID_VALUE, "count is negative"};
  if (error == GL_NO_ERROR && type != GL_UNSIGNED_BYTE && type != GL_UNSIGNED_SHORT && type != GL_UNSIGNED_INT)
    error = {GL_INVALID_ENUM, "type is not GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT or GL_UNSIGNED_INT"};
  std::vector<raster::VertexInput> vertices;
  std::optional<float> last_index;
  if (error == GL_NO_ERROR && count > 0 && array_sources(ctx).vertex)
    indices = element_indices(ctx, indices, size_t(count) * gl_type_size(type));
  if (error == GL_NO_ERROR && indices && array_sources(ctx).vertex) {
    if (type == GL_UNSIGNED_BYTE)
      last_index = fetch_indexed(ctx, count, static_cast<const GLubyte*>(indices), vertices);
    else if (type == GL_UNSIGNED_SHORT)
      last_index = fetch_indexed(ctx, count, static_cast<const GLushort*>(indices), vertices);
    else
      last_index = fetch_indexed(ctx, count, static_cast<const GLuint*>(indices), vertices);
  }
  record_draw(ctx, mode, std::move(vertices), error, last_index);
}

// The texture image calls copy the client pixels only when they read them: the argument checks
// that depend on no state come first, and the list runs the call with all its checks.
// TexImage with a proxy target is executed at once, not compiled (GL 1.5 5.4).
void compile_TexImage2D(Context& ctx, GLenum target, GLint level, GLint internalformat, GLsizei width,
                        GLsizei height, GLint border, GLenum format, GLenum type, const void* pixels) {
  if (is_proxy(target))
    return TexImage2D(ctx, target, level, internalformat, width, height, border, format, type, pixels);
  const bool reads = tex_image_error(target, 2, level, internalformat, width, height, 1, border, format, type) ==
                     GL_NO_ERROR;
  auto image = texture_pixels(ctx, reads, width, height, 1, false, format, type, pixels);
  ctx.record_list_command([=, image = std::move(image)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    with_packed_unpack(c, [&] {
      TexImage2D(c, target, level, internalformat, width, height, border, format, type,
                 image.empty() ? nullptr : image.data());
    });
  });
}

void compile_TexImage1D(Context& ctx, GLenum target, GLint level, GLint internalformat, GLsizei width,
                        GLint border, GLenum format, GLenum type, const void* pixels) {
  if (is_proxy(target)) return TexImage1D(ctx, target, level, internalformat, width, border, format, type, pixels);
  const bool reads = tex_image_error(target, 1, level, internalformat, width, 1, 1, border, format, type) ==
                     GL_NO_ERROR;
  auto image = texture_pixels(ctx, reads, width, 1, 1, false, format, type, pixels);
  ctx.record_list_command([=, image = std::move(image)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    with_packed_unpack(c, [&] {
      TexImage1D(c, target, level, internalformat, width, border, format, type, image.empty() ? nullptr : image.data());
    });
  });
}

void compile_TexSubImage2D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width,
                           GLsizei height, GLenum format, GLenum type, const void* pixels) {
  const bool reads = tex_sub_image_may_read(target, 2, level, width, height, 1, format, type);
  auto image = texture_pixels(ctx, reads, width, height, 1, false, format, type, pixels);
  ctx.record_list_command([=, image = std::move(image)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    with_packed_unpack(c, [&] {
      TexSubImage2D(c, target, level, xoffset, yoffset, width, height, format, type,
                    image.empty() ? nullptr : image.data());
    });
  });
}

void compile_TexSubImage1D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format,
                           GLenum type, const void* pixels) {
  const bool reads = tex_sub_image_may_read(target, 1, level, width, 1, 1, format, type);
  auto image = texture_pixels(ctx, reads, width, 1, 1, false, format, type, pixels);
  ctx.record_list_command([=, image = std::move(image)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    with_packed_unpack(c, [&] {
      TexSubImage1D(c, target, level, xoffset, width, format, type, image.empty() ? nullptr : image.data());
    });
  });
}

void compile_TexImage3D(Context& ctx, GLenum target, GLint level, GLint internalformat, GLsizei width,
                        GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type, const void* pixels) {
  if (is_proxy(target))
    return TexImage3D(ctx, target, level, internalformat, width, height, depth, border, format, type, pixels);
  const bool reads = tex_image_error(target, 3, level, internalformat, width, height, depth, border, format,
                                     type) == GL_NO_ERROR;
  auto image = texture_pixels(ctx, reads, width, height, depth, true, format, type, pixels);
  ctx.record_list_command([=, image = std::move(image)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    with_packed_unpack(c, [&] {
      TexImage3D(c, target, level, internalformat, width, height, depth, border, format, type,
                 image.empty() ? nullptr : image.data());
    });
  });
}

void compile_TexImage3DEXT(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width,
                           GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type, const void* pixels) {
  compile_TexImage3D(ctx, target, level, GLint(internalformat), width, height, depth, border, format, type, pixels);
}

void compile_TexSubImage3D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                           GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type,
                           const void* pixels) {
  const bool reads = tex_sub_image_may_read(target, 3, level, width, height, depth, format, type);
  auto image = texture_pixels(ctx, reads, width, height, depth, true, format, type, pixels);
  ctx.record_list_command([=, image = std::move(image)](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    with_packed_unpack(c, [&] {
      TexSubImage3D(c, target, level, xoffset, yoffset, zoffset, width, height, depth, format, type,
                    image.empty() ? nullptr : image.data());
    });
  });
}

void compile_TexSubImage3DEXT(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                              GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type,
                              const void* pixels) {
  compile_TexSubImage3D(ctx, target, level, xoffset, yoffset, zoffset, width, height, depth, format, type, pixels);
}

}  // namespace pineda::gl
