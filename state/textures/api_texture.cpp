// Texture objects, images and parameters (1D, 2D, 3D, cube map and rectangle textures).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/es2/es2_rules.h"
#include "state/context.h"
#include "state/es1/es1_enums.h"
#include "state/es1/tex_image_rules.h"
#include "state/framebuffers/packed_depth_stencil.h"
#include "state/enum_translate.h"
#include "state/limits.h"
#include "state/buffers/pixel_buffer.h"
#include "state/pixels/pixel_format.h"
#include "state/pixels/pixel_state.h"
#include "state/pixels/pixel_unpack.h"
#include "state/textures/tex_image_checks.h"
#include "state/textures/texture_format.h"
#include "state/textures/texture_rectangle.h"
#include "state/textures/sampling_params.h"

namespace pineda::gl {
namespace {

using raster::TexBaseFormat;

TextureObject& bound_texture(Context& ctx, TexTarget kind) {
  const GLuint name = bound_name(ctx.texture_units[ctx.active_texture], kind);
  return ctx.textures.get_or_create(name, binding_enum(kind));
}

// The texture a binding target (glTexParameter) names, or null for another enum.
TextureObject* bound_texture(Context& ctx, GLenum target) {
  TexTarget kind;
  return binding_target(target, kind) ? &bound_texture(ctx, kind) : nullptr;
}

// The texture an image command or level query addresses: the bound one, or a proxy.
TextureObject& image_texture(Context& ctx, const ImageTarget& target) {
  if (!target.proxy) resolve_rendered_textures(ctx);  // rendering queued into it lands first
  return target.proxy ? ctx.textures.proxy(target.kind) : bound_texture(ctx, target.kind);
}

// The image target of a command whose images have `dims` dimensions; false (INVALID_ENUM)
// for any other target, and for proxies when `proxy_ok` is false.
bool image_target_of(GLenum target, int dims, bool proxy_ok, ImageTarget& out) {
  return image_target(target, out) && image_dimensions(out.kind) == dims && (proxy_ok || !out.proxy);
}

bool valid_format_type(Context& ctx, GLenum format, GLenum type) {
  const GlError error = texture_image_format_type_error(format, type);
  if (error != GL_NO_ERROR) ctx.record_error(error);
  return error == GL_NO_ERROR;
}

// A client image and the region of a texture level it fills.
struct ClientBox {
  int x = 0, y = 0, z = 0;  // the region's offset in the level
  int width = 0, height = 0, depth = 1;
  int border_x = 0, border_y = 0, border_z = 0;  // border texels of the source skipped on each side
  bool volume = false;  // a 3D image: its slices follow IMAGE_HEIGHT and SKIP_IMAGES
};

// Copies a client image into the texels of `level` at the box's offset. A 3D image is read
// as one tall 2D image whose slice k starts at row (SKIP_IMAGES + k) * IMAGE_HEIGHT (or the
// image's height when IMAGE_HEIGHT is 0).
void unpack_into(Context& ctx, TextureLevelData& level, const TextureFormat& storage, const ClientBox& box,
                 GLenum format, GLenum type, const void* pixels) {
  if (!pixels || box.width <= 0 || box.height <= 0 || box.depth <= 0) return;  // an empty image has no texels
  const ColorImageReader source(ctx, box.width + 2 * box.border_x, format, type, pixels);  // GL 1.5 3.8.1
  const int full_height = box.height + 2 * box.border_y;
  const int64_t image_rows = ctx.unpack.image_height > 0 ? ctx.unpack.image_height : full_height;
  const int64_t skip_images = box.volume ? ctx.unpack.skip_images : 0;
  const bool bytes = keeps_bytes(storage);
  std::vector<float> rgba_row;
  for (int z = 0; z < box.depth; ++z)
    for (int y = 0; y < box.height; ++y) {
      const int64_t row = (skip_images + z + box.border_z) * image_rows + y + box.border_y;
      uint32_t* dst = &level.texels[(size_t(box.z + z) * level.height + size_t(box.y + y)) * level.width + box.x];
      if (bytes && source.rgba8_texels(row, box.border_x, box.width, dst)) {
        reduce_rgba8_to_base(dst, box.width, storage.base);
        continue;
      }
      rgba_row.resize(4 * size_t(box.width));
      source.read_row(row, box.border_x, box.width, rgba_row.data());
      to_texels(rgba_row.data(), box.width, storage, dst);
    }
}

// The same for a depth texture (1D or 2D): DEPTH_COMPONENT data through DEPTH_SCALE/BIAS,
// as the format keeps it (depth_texel).
void unpack_depth_into(Context& ctx, TextureLevelData& level, const TextureFormat& storage, const ClientBox& box, GLenum type,
                       const void* pixels) {
  if (!pixels) return;
  const int full_width = box.width + 2 * box.border_x, full_height = box.height + 2 * box.border_y;
  const std::vector<double> depths = unpack_depth_image(ctx, full_width, full_height, type, pixels);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x)
      level.texels[size_t(box.y + y) * level.width + box.x + x] =
          depth_texel(depths[size_t(y + box.border_y) * full_width + x + box.border_x], storage);
}

// The same for packed DEPTH_STENCIL data of `type`: its depth, and its stencil where the texture
// keeps stencil (a depth format takes the depth alone).
void unpack_depth_stencil_into(Context& ctx, TextureLevelData& level, const TextureFormat& storage, const ClientBox& box,
                               GLenum type, const void* pixels) {
  if (!pixels) return;
  const int full_width = box.width + 2 * box.border_x, full_height = box.height + 2 * box.border_y;
  std::vector<double> depths;
  std::vector<int64_t> stencils;
  unpack_depth_stencil_image(ctx, full_width, full_height, type, pixels, depths, stencils);
  if (storage.stencil) level.stencil.resize(level.texels.size(), 0);  // a level made by mipmap generation has none yet
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const size_t src = size_t(y + box.border_y) * full_width + x + box.border_x;
      const size_t dst = size_t(box.y + y) * level.width + box.x + x;
      level.texels[dst] = depth_texel(depths[src], storage);
      if (storage.stencil) level.stencil[dst] = static_cast<uint8_t>(stencils[src] & 0xff);
    }
}

// Client pixels of `format` into a level: depth data (DEPTH_COMPONENT into the depth of a depth or
// depth-stencil level, whose stencil stays; DEPTH_STENCIL into either) or colour data.
void unpack_texels(Context& ctx, TextureLevelData& level, const TextureFormat& storage, const ClientBox& box,
                   GLenum format, GLenum type, const void* pixels) {
  if (format == GL_DEPTH_STENCIL) unpack_depth_stencil_into(ctx, level, storage, box, type, pixels);
  else if (format == GL_DEPTH_COMPONENT) unpack_depth_into(ctx, level, storage, box, type, pixels);
  else unpack_into(ctx, level, storage, box, format, type, pixels);
}

bool valid_depth_use(Context& ctx, const TextureFormat& storage, TexTarget kind, GLenum format) {
  if (depth_use_allowed(storage, kind, format)) return true;
  ctx.record_error(GL_INVALID_OPERATION,
                   "format and internalformat differ in depth or stencil, or the target is not 1D, 2D or rectangle");
  return false;
}

// glTexImage1D/2D/3D: height and depth are 1 where the target has no such dimension.
void tex_image(Context& ctx, GLenum target_enum, int dims, GLint level, GLint internal_format, GLsizei width,
               GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type, const void* pixels) {
  const GlError error =
      tex_image_error(target_enum, dims, level, internal_format, width, height, depth, border, format, type);
  if (error != GL_NO_ERROR) return ctx.record_error(error);
  ImageTarget target;
  image_target(target_enum, target);
  const TextureFormat storage = *texture_format(internal_format);
  const int inner_w = width - 2 * border;
  const int inner_h = dims >= 2 ? height - 2 * border : 1;
  const int inner_d = dims == 3 ? depth - 2 * border : 1;
  const GLint recorded_format = stored_internal_format(internal_format);
  TextureObject& tex = image_texture(ctx, target);
  if (tex.immutable_levels > 0)  // ARB_texture_storage: even an image of the same size and format
    return ctx.record_error(GL_INVALID_OPERATION, "the texture's storage is immutable (glTexStorage)");
  std::vector<TextureLevelData>& levels = tex.face_levels(target.face);
  const int level_max = max_texture_size(target.kind) >> level;
  if (target.proxy) {  // GL 1.5 3.8.1: a proxy level takes the image's state when it fits, zeros otherwise
    if (levels.size() <= size_t(level)) levels.resize(level + 1);
    const bool too_large = inner_w > level_max || inner_h > level_max || inner_d > level_max;
    levels[level] = too_large ? TextureLevelData{}
                              : TextureLevelData{inner_w, inner_h, inner_d, border, recorded_format, storage.base, {}, {}};
    return;
  }
  if (!unpack_pixels(ctx, pixels, client_image_extent(ctx.unpack, width, height, depth, dims == 3, format, type)))
    return;
  // Allocated before the level changes, so that running out of memory leaves the texture as it was.
  TextureLevelData image{inner_w, inner_h, inner_d, border, recorded_format, storage.base, {}, {}};
  image.texels.assign(size_t(inner_w) * inner_h * inner_d, 0u);
  if (storage.stencil) image.stencil.assign(size_t(inner_w) * inner_h * inner_d, 0);
  if (levels.size() <= size_t(level)) levels.resize(level + 1);
  TextureLevelData& l = levels[level];
  l = std::move(image);
  const ClientBox box{0, 0, 0, inner_w, inner_h, inner_d, border, dims >= 2 ? border : 0, dims == 3 ? border : 0,
                      dims == 3};
  unpack_texels(ctx, l, storage, box, format, type, pixels);
  tex.level_changed(level, target.face);
}

// glTexSubImage1D/2D/3D into the bound texture of `target` (no proxies).
void tex_sub_image(Context& ctx, const ImageTarget& target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                   GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, const void* pixels) {
  TextureObject& tex = image_texture(ctx, target);
  if (!valid_format_type(ctx, format, type)) return;
  if (level < 0) return ctx.record_error(GL_INVALID_VALUE, "level is negative");
  if (level > max_texture_level(target.kind))
    return ctx.record_error(GL_INVALID_VALUE, "level is above log2 of the maximum texture size");
  if (width < 0 || height < 0 || depth < 0)
    return ctx.record_error(GL_INVALID_VALUE, "width, height or depth is negative");
  std::vector<TextureLevelData>& levels = tex.face_levels(target.face);
  if (size_t(level) >= levels.size() || levels[level].width == 0)
    return ctx.record_error(GL_INVALID_OPERATION, "the level has no image to replace");
  TextureLevelData& l = levels[level];
  if (xoffset < 0 || yoffset < 0 || zoffset < 0 || int64_t(xoffset) + width > l.width ||
      int64_t(yoffset) + height > l.height || int64_t(zoffset) + depth > l.depth)
    return ctx.record_error(GL_INVALID_VALUE, "the offsets and sizes reach outside the level's image");
  const TextureFormat storage = *texture_format(l.internal_format);
  if (!valid_depth_use(ctx, storage, target.kind, format)) return;
  const bool volume = target.kind == TexTarget::T3D;
  if (!unpack_pixels(ctx, pixels, client_image_extent(ctx.unpack, width, height, depth, volume, format, type))) return;
  // The last draw's state still holds the images it sampled (each draw takes them again): let
  // them go, so that texels no queued draw reads are changed in place.
  for (raster::DrawState* state : {&ctx.draw_state, &ctx.programs.draw_state})
    for (raster::TextureUnit& unit : state->texture_units) unit.image.reset();
  tex.before_texels_change(level, target.face);
  const ClientBox box{xoffset, yoffset, zoffset, width, height, depth, 0, 0, 0, volume};
  unpack_texels(ctx, l, storage, box, format, type, pixels);
  tex.box_changed(level, target.face, {xoffset, yoffset, zoffset, width, height, depth});
}

bool swizzle_source(GLenum e) {
  return e == GL_RED || e == GL_GREEN || e == GL_BLUE || e == GL_ALPHA || e == GL_ZERO || e == GL_ONE;
}

// Sets one parameter; returns the error the spec names for a bad one.
GlError set_tex_parameter(TextureObject& tex, GLenum pname, const GLfloat* v) {
  TexParams& p = tex.params;
  const GLenum e = enum_from_float(v[0]);
  if (tex.target == GL_TEXTURE_RECTANGLE_ARB)
    if (const GlError error = rectangle_parameter_error(pname, v[0]); error != GL_NO_ERROR) return error;
  // No snapshot to drop: the snapshots check their keys (texture_object.h).
  if (is_sampling_param(pname)) return set_sampling_param(p, pname, v);
  switch (pname) {
    case GL_TEXTURE_PRIORITY:
      p.priority = std::clamp(v[0], 0.f, 1.f);
      return GL_NO_ERROR;
    case GL_TEXTURE_BASE_LEVEL:
    case GL_TEXTURE_MAX_LEVEL: {
      if (!(v[0] >= 0.f)) return {GL_INVALID_VALUE, "the level is negative"};  // or NaN
      const GLint level = v[0] >= 2147483648.f ? 2147483647 : GLint(v[0]);
      (pname == GL_TEXTURE_BASE_LEVEL ? p.base_level : p.max_level) = tex.clamped_level_param(pname, level);
      break;
    }
    case GL_GENERATE_MIPMAP:
      if (e != GL_TRUE && e != GL_FALSE) return {GL_INVALID_ENUM, "param is not GL_TRUE or GL_FALSE"};
      p.generate_mipmap = e == GL_TRUE;
      return GL_NO_ERROR;
    case GL_DEPTH_TEXTURE_MODE:
      if (e != GL_LUMINANCE && e != GL_INTENSITY && e != GL_ALPHA)
        return {GL_INVALID_ENUM, "param is not GL_LUMINANCE, GL_INTENSITY or GL_ALPHA"};
      p.depth_mode = e;
      break;
    case GL_TEXTURE_SWIZZLE_R:
    case GL_TEXTURE_SWIZZLE_G:
    case GL_TEXTURE_SWIZZLE_B:
    case GL_TEXTURE_SWIZZLE_A:
      if (!swizzle_source(e)) return {GL_INVALID_ENUM, "param is not GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_ZERO or GL_ONE"};
      p.swizzle[pname - GL_TEXTURE_SWIZZLE_R] = e;
      break;
    case GL_TEXTURE_SWIZZLE_RGBA:
      for (int i = 0; i < 4; ++i)
        if (!swizzle_source(enum_from_float(v[i])))
          return {GL_INVALID_ENUM, "a value is not GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA, GL_ZERO or GL_ONE"};
      for (int i = 0; i < 4; ++i) p.swizzle[i] = enum_from_float(v[i]);
      break;
    case GL_TEXTURE_CROP_RECT_OES:  // only glDrawTex reads it: the sampled image is unchanged
      for (int i = 0; i < 4; ++i)  // integers, as the extension keeps them; NaN becomes 0
        p.crop_rect[i] = std::isnan(v[i]) ? 0 : GLint(std::clamp(v[i], -2147483648.f, 2147483520.f));
      return GL_NO_ERROR;
    default:
      return {GL_INVALID_ENUM, "pname is not a texture parameter"};
  }
  tex.changed();
  return GL_NO_ERROR;
}

// OES_draw_texture's crop rectangle is OpenGL ES 1.1's only.
bool known_pname(const Context& ctx, GLenum pname) {
  if (pname == GL_TEXTURE_IMMUTABLE_FORMAT) return !ctx.es1() && !ctx.es2();  // ARB_texture_storage's
  return pname != GL_TEXTURE_CROP_RECT_OES || ctx.es1();
}

void tex_parameter(Context& ctx, GLenum target, GLenum pname, const GLfloat* v) {
  TextureObject* tex = bound_texture(ctx, target);
  if (!tex) return ctx.record_error(GL_INVALID_ENUM, "target is not a texture target");
  if (!known_pname(ctx, pname)) return ctx.record_error(GL_INVALID_ENUM, "pname is an OpenGL ES 1.1 parameter");
  if (ctx.es2() && !es2_tex_parameter_allowed(pname, enum_from_float(v[0])))
    return ctx.record_error(GL_INVALID_ENUM, "not a wrap mode of OpenGL ES 2.0");
  if (const GlError error = set_tex_parameter(*tex, pname, v); error != GL_NO_ERROR) ctx.record_error(error);
}

bool is_vector_tex_param(GLenum pname) {
  return pname == GL_TEXTURE_BORDER_COLOR || pname == GL_TEXTURE_CROP_RECT_OES || pname == GL_TEXTURE_SWIZZLE_RGBA;
}

// The values of a texture parameter; `colour` tells whether integer queries map them as colours.
bool get_tex_parameter(Context& ctx, GLenum target, GLenum pname, float out[4], int& count, bool& colour) {
  TextureObject* tex = bound_texture(ctx, target);
  if (!tex || !known_pname(ctx, pname)) return false;
  const TexParams& p = tex->params;
  if (get_sampling_param(p, pname, out, count, colour)) return true;
  count = 1;
  colour = false;
  switch (pname) {
    case GL_TEXTURE_PRIORITY: out[0] = p.priority; colour = true; return true;
    case GL_TEXTURE_RESIDENT: out[0] = 1.f; return true;
    case GL_TEXTURE_BASE_LEVEL: out[0] = float(p.base_level); return true;
    case GL_TEXTURE_MAX_LEVEL: out[0] = float(p.max_level); return true;
    case GL_GENERATE_MIPMAP: out[0] = p.generate_mipmap ? 1.f : 0.f; return true;
    case GL_DEPTH_TEXTURE_MODE: out[0] = float(p.depth_mode); return true;
    case GL_TEXTURE_CROP_RECT_OES:
      std::copy(p.crop_rect, p.crop_rect + 4, out);
      count = 4;
      return true;
    case GL_TEXTURE_SWIZZLE_R: case GL_TEXTURE_SWIZZLE_G: case GL_TEXTURE_SWIZZLE_B: case GL_TEXTURE_SWIZZLE_A:
      out[0] = float(p.swizzle[pname - GL_TEXTURE_SWIZZLE_R]);
      return true;
    case GL_TEXTURE_SWIZZLE_RGBA:
      for (int i = 0; i < 4; ++i) out[i] = float(p.swizzle[i]);
      count = 4;
      return true;
    case GL_TEXTURE_IMMUTABLE_FORMAT: out[0] = tex->immutable_levels > 0 ? 1.f : 0.f; return true;
    default: return false;
  }
}

GLint component_type(int bits) { return bits ? GL_UNSIGNED_NORMALIZED : GL_NONE; }

bool get_tex_level_parameter(Context& ctx, const ImageTarget& target, GLint level, GLenum pname, GLint& out) {
  const std::vector<TextureLevelData>& levels = image_texture(ctx, target).face_levels(target.face);
  const TextureLevelData empty;
  const TextureLevelData& l = size_t(level) < levels.size() ? levels[level] : empty;
  const int dims = image_dimensions(target.kind);
  const std::optional<TextureFormat> storage = l.width > 0 ? texture_format(l.internal_format) : std::nullopt;
  const bool defined = storage.has_value();
  const TextureFormat sizes = storage.value_or(TextureFormat{});
  switch (pname) {
    case GL_TEXTURE_WIDTH: out = defined ? l.width + 2 * l.border : 0; return true;
    case GL_TEXTURE_HEIGHT: out = defined ? (dims < 2 ? 1 : l.height + 2 * l.border) : 0; return true;
    case GL_TEXTURE_DEPTH: out = defined ? (dims < 3 ? 1 : l.depth + 2 * l.border) : 0; return true;
    case GL_TEXTURE_BORDER: out = defined ? l.border : 0; return true;
    case GL_TEXTURE_INTERNAL_FORMAT: out = defined ? l.internal_format : 1; return true;
    case GL_TEXTURE_RED_SIZE: out = sizes.red; return true;
    case GL_TEXTURE_GREEN_SIZE: out = sizes.green; return true;
    case GL_TEXTURE_BLUE_SIZE: out = sizes.blue; return true;
    case GL_TEXTURE_ALPHA_SIZE: out = sizes.alpha; return true;
    case GL_TEXTURE_LUMINANCE_SIZE: out = sizes.luminance; return true;
    case GL_TEXTURE_INTENSITY_SIZE: out = sizes.intensity; return true;
    case GL_TEXTURE_DEPTH_SIZE: out = sizes.depth; return true;
    case GL_TEXTURE_STENCIL_SIZE: out = sizes.stencil; return true;  // Mesa answers it in any version
    // GL 3.0's component types (ARB_texture_float's queries): NONE where the format has no such component.
    case GL_TEXTURE_RED_TYPE: out = component_type(sizes.red); return true;
    case GL_TEXTURE_GREEN_TYPE: out = component_type(sizes.green); return true;
    case GL_TEXTURE_BLUE_TYPE: out = component_type(sizes.blue); return true;
    case GL_TEXTURE_ALPHA_TYPE: out = component_type(sizes.alpha); return true;
    case GL_TEXTURE_LUMINANCE_TYPE: out = component_type(sizes.luminance); return true;
    case GL_TEXTURE_INTENSITY_TYPE: out = component_type(sizes.intensity); return true;
    case GL_TEXTURE_DEPTH_TYPE: out = sizes.depth_float ? GL_FLOAT : component_type(sizes.depth); return true;
    case GL_TEXTURE_COMPRESSED: out = GL_FALSE; return true;  // no image is ever compressed
    default: return false;
  }
}

// glGetTexLevelParameter's checks: the target (not TEXTURE_CUBE_MAP itself), then the level.
bool level_parameter(Context& ctx, GLenum target, GLint level, GLenum pname, GLint& out) {
  ImageTarget t;
  if (!image_target(target, t)) {
    ctx.record_error(GL_INVALID_ENUM, "target is not a texture image target");
    return false;
  }
  if (level < 0 || level > max_texture_level(t.kind)) {
    ctx.record_error(GL_INVALID_VALUE, "level is negative or above log2 of the maximum texture size");
    return false;
  }
  if (pname == GL_TEXTURE_COMPRESSED_IMAGE_SIZE) {
    // Only compressed images have it, and none is: INVALID_OPERATION for a defined level (as
    // Mesa), 0 for an undefined one.
    const std::vector<TextureLevelData>& levels = image_texture(ctx, t).face_levels(t.face);
    out = 0;
    if (size_t(level) >= levels.size() || levels[level].width == 0) return true;
    ctx.record_error(GL_INVALID_OPERATION, "the level's image is not compressed");
    return false;
  }
  if (get_tex_level_parameter(ctx, t, level, pname, out)) return true;
  ctx.record_error(GL_INVALID_ENUM, "pname is not a texture level parameter");
  return false;
}

}  // namespace

void GenTextures(Context& ctx, GLsizei n, GLuint* textures) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (textures) ctx.textures.generate(n, textures);
}

void DeleteTextures(Context& ctx, GLsizei n, const GLuint* textures) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (!textures) return;
  for (GLsizei i = 0; i < n; ++i) {
    const GLuint name = textures[i];
    if (name == 0) continue;
    for (TextureUnitState& unit : ctx.texture_units)  // deleting a bound texture binds 0
      for (int k = 0; k < kTexTargetCount; ++k)
        if (GLuint& bound = bound_name(unit, TexTarget(k)); bound == name) bound = 0;
    if (ctx.textures.find(name)) detach_deleted(ctx, GL_TEXTURE, name);
    ctx.textures.remove(name);
    ctx.debug.forget_label(GL_TEXTURE, name);
  }
}

void BindTexture(Context& ctx, GLenum target, GLuint texture) {
  TexTarget kind;
  if (!binding_target(target, kind)) return ctx.record_error(GL_INVALID_ENUM, "target is not a texture target");
  if (texture != 0) {
    TextureObject* existing = ctx.textures.find(texture);
    if (existing && existing->target != 0 && existing->target != target)
      return ctx.record_error(GL_INVALID_OPERATION, "the texture was first bound to another target");
    TextureObject& tex = ctx.textures.get_or_create(texture, target);
    if (tex.target == 0) {
      tex.target = target;
      tex.params = default_tex_params(kind);
    }
  }
  bound_name(ctx.texture_units[ctx.active_texture], kind) = texture;
}

GLboolean IsTexture(Context& ctx, GLuint texture) { return ctx.textures.is_texture(texture) ? GL_TRUE : GL_FALSE; }

void TexImage1D(Context& ctx, GLenum target, GLint level, GLint internalformat, GLsizei width, GLint border,
                GLenum format, GLenum type, const void* pixels) {
  tex_image(ctx, target, 1, level, internalformat, width, 1, 1, border, format, type, pixels);
}

void TexImage2D(Context& ctx, GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height,
                GLint border, GLenum format, GLenum type, const void* pixels) {
  if (ctx.es1() && !es1_tex_image_allowed(ctx, internalformat, border, format, type)) return;
  if (ctx.es2()) {
    if (!es2_tex_image_allowed(ctx, internalformat, border, format, type)) return;
    internalformat = es2_storage_format(internalformat);
  }
  tex_image(ctx, target, 2, level, internalformat, width, height, 1, border, format, type, pixels);
}

void TexImage3D(Context& ctx, GLenum target, GLint level, GLint internalformat, GLsizei width, GLsizei height,
                GLsizei depth, GLint border, GLenum format, GLenum type, const void* pixels) {
  tex_image(ctx, target, 3, level, internalformat, width, height, depth, border, format, type, pixels);
}

void TexImage3DEXT(Context& ctx, GLenum target, GLint level, GLenum internalformat, GLsizei width, GLsizei height,
                   GLsizei depth, GLint border, GLenum format, GLenum type, const void* pixels) {
  TexImage3D(ctx, target, level, GLint(internalformat), width, height, depth, border, format, type, pixels);
}

void TexSubImage1D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLsizei width, GLenum format, GLenum type,
                   const void* pixels) {
  ImageTarget t;
  if (!image_target_of(target, 1, false, t)) return ctx.record_error(GL_INVALID_ENUM, "target is not GL_TEXTURE_1D");
  tex_sub_image(ctx, t, level, xoffset, 0, 0, width, 1, 1, format, type, pixels);
}

void TexSubImage2D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLsizei width,
                   GLsizei height, GLenum format, GLenum type, const void* pixels) {
  ImageTarget t;
  if (!image_target_of(target, 2, false, t))
    return ctx.record_error(GL_INVALID_ENUM, "target is not a 2D texture image target");
  if (ctx.es2() && !es2_tex_sub_image_allowed(ctx, format, type)) return;
  tex_sub_image(ctx, t, level, xoffset, yoffset, 0, width, height, 1, format, type, pixels);
}

void TexSubImage3D(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                   GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, const void* pixels) {
  ImageTarget t;
  if (!image_target_of(target, 3, false, t)) return ctx.record_error(GL_INVALID_ENUM, "target is not GL_TEXTURE_3D");
  tex_sub_image(ctx, t, level, xoffset, yoffset, zoffset, width, height, depth, format, type, pixels);
}

void TexSubImage3DEXT(Context& ctx, GLenum target, GLint level, GLint xoffset, GLint yoffset, GLint zoffset,
                      GLsizei width, GLsizei height, GLsizei depth, GLenum format, GLenum type, const void* pixels) {
  TexSubImage3D(ctx, target, level, xoffset, yoffset, zoffset, width, height, depth, format, type, pixels);
}

// The border colour takes only the vector forms, but a display list holds the scalar forms as
// vector ones with (param, 0, 0, 0), so there they are accepted, as in Mesa.
void TexParameterf(Context& ctx, GLenum target, GLenum pname, GLfloat param) {
  if (is_vector_tex_param(pname) && !ctx.compiling_list())
    return ctx.record_error(GL_INVALID_ENUM, "pname takes a vector: use glTexParameterfv or glTexParameteriv");
  const GLfloat v[4] = {param, 0, 0, 0};
  tex_parameter(ctx, target, pname, v);
}
void TexParameteri(Context& ctx, GLenum target, GLenum pname, GLint param) { TexParameterf(ctx, target, pname, GLfloat(param)); }
void compile_TexParameterf(Context& ctx, GLenum target, GLenum pname, GLfloat param) {
  ctx.record_list_command([=](Context& c) {
    if (c.inside_begin_end()) return c.record_error(GL_INVALID_OPERATION, "called between glBegin and glEnd");
    const GLfloat v[4] = {param, 0, 0, 0};
    tex_parameter(c, target, pname, v);
  });
}
void compile_TexParameteri(Context& ctx, GLenum target, GLenum pname, GLint param) {
  compile_TexParameterf(ctx, target, pname, GLfloat(param));
}
void TexParameterfv(Context& ctx, GLenum target, GLenum pname, const GLfloat* params) {
  if (params) tex_parameter(ctx, target, pname, params);
}
void TexParameteriv(Context& ctx, GLenum target, GLenum pname, const GLint* params) {
  if (!params) return;
  GLfloat v[4] = {GLfloat(params[0]), 0, 0, 0};
  if (pname == GL_TEXTURE_BORDER_COLOR)  // integer colours map [-2^31, 2^31-1] onto [-1, 1]
    for (int i = 0; i < 4; ++i) v[i] = colour_from_int_param(params[i]);
  if (pname == GL_TEXTURE_CROP_RECT_OES || pname == GL_TEXTURE_SWIZZLE_RGBA)
    for (int i = 0; i < 4; ++i) v[i] = GLfloat(params[i]);
  tex_parameter(ctx, target, pname, v);
}

void GetTexParameterfv(Context& ctx, GLenum target, GLenum pname, GLfloat* params) {
  float v[4];
  int count;
  bool colour;
  if (!get_tex_parameter(ctx, target, pname, v, count, colour))
    return ctx.record_error(GL_INVALID_ENUM, "target is not a texture target or pname is not a texture parameter");
  if (params) std::copy(v, v + count, params);
}
void GetTexParameteriv(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  float v[4];
  int count;
  bool colour;
  if (!get_tex_parameter(ctx, target, pname, v, count, colour))
    return ctx.record_error(GL_INVALID_ENUM, "target is not a texture target or pname is not a texture parameter");
  if (!params) return;
  for (int i = 0; i < count; ++i) params[i] = colour ? colour_int_param(v[i]) : truncate_int_param(v[i]);
}

void GetTexLevelParameteriv(Context& ctx, GLenum target, GLint level, GLenum pname, GLint* params) {
  GLint v;
  if (level_parameter(ctx, target, level, pname, v) && params) *params = v;
}
void GetTexLevelParameterfv(Context& ctx, GLenum target, GLint level, GLenum pname, GLfloat* params) {
  GLint v;
  if (level_parameter(ctx, target, level, pname, v) && params) *params = GLfloat(v);
}

void PrioritizeTextures(Context& ctx, GLsizei n, const GLuint* textures, const GLfloat* priorities) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (!textures || !priorities) return;
  for (GLsizei i = 0; i < n; ++i)
    if (TextureObject* t = ctx.textures.find(textures[i])) t->params.priority = std::clamp(priorities[i], 0.f, 1.f);
}

// Every texture is resident in a software renderer.
GLboolean AreTexturesResident(Context& ctx, GLsizei n, const GLuint* textures, GLboolean* residences) {
  if (n < 0) {
    ctx.record_error(GL_INVALID_VALUE, "n is negative");
    return GL_FALSE;
  }
  if (!textures) return GL_TRUE;
  for (GLsizei i = 0; i < n; ++i)
    if (textures[i] == 0 || !ctx.textures.is_texture(textures[i])) {
      ctx.record_error(GL_INVALID_VALUE, "a name in textures is zero or not a texture");
      return GL_FALSE;
    }
  return GL_TRUE;
}

}  // namespace pineda::gl
