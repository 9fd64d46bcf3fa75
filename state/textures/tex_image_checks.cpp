#include "state/textures/tex_image_checks.h"

#include <optional>

#include "state/pixels/pixel_format.h"

namespace pineda {
namespace {

bool image_target_of(GLenum target, int dims, bool proxy_ok, ImageTarget& out) {
  return image_target(target, out) && image_dimensions(out.kind) == dims && (proxy_ok || !out.proxy);
}

// The targets whose images may hold depth: 1D, 2D and rectangle textures (as Mesa).
bool depth_target(TexTarget kind) { return kind == TexTarget::T1D || kind == TexTarget::T2D || kind == TexTarget::Rect; }

}  // namespace

bool depth_use_allowed(const TextureFormat& storage, TexTarget kind, GLenum format) {
  const bool depth_storage = storage.depth > 0 || storage.stencil;
  const bool depth_data = format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL;
  return depth_storage == depth_data && (!depth_storage || depth_target(kind));
}

GlError tex_image_error(GLenum target, int dims, GLint level, GLint internal_format, GLsizei width, GLsizei height,
                        GLsizei depth, GLint border, GLenum format, GLenum type) {
  ImageTarget t;
  if (!image_target_of(target, dims, true, t)) return {GL_INVALID_ENUM, "target is not a texture image target of the call"};
  if (const GlError error = texture_image_format_type_error(format, type); error != GL_NO_ERROR) return error;
  const std::optional<TextureFormat> storage = texture_format(internal_format);
  if (level < 0) return {GL_INVALID_VALUE, "level is negative"};
  if (level > max_texture_level(t.kind)) return {GL_INVALID_VALUE, "level is above log2 of the maximum texture size"};
  if (!storage) return {GL_INVALID_VALUE, "internalformat is not a texture format"};
  if (border != 0 && border != 1) return {GL_INVALID_VALUE, "border is not 0 or 1"};
  const int64_t inner_w = int64_t(width) - 2 * border;
  const int64_t inner_h = dims >= 2 ? int64_t(height) - 2 * border : 1;
  const int64_t inner_d = dims == 3 ? int64_t(depth) - 2 * border : 1;
  if (inner_w < 0) return {GL_INVALID_VALUE, width < 0 ? "width is negative" : "width is less than twice border"};
  if (inner_h < 0) return {GL_INVALID_VALUE, height < 0 ? "height is negative" : "height is less than twice border"};
  if (inner_d < 0) return {GL_INVALID_VALUE, depth < 0 ? "depth is negative" : "depth is less than twice border"};
  if (t.kind == TexTarget::Cube && width != height) return {GL_INVALID_VALUE, "a cube map face's width and height differ"};
  if (!depth_use_allowed(*storage, t.kind, format))
    return {GL_INVALID_OPERATION, "format and internalformat differ in depth or stencil, or the target is not 1D, 2D or rectangle"};
  const int level_max = max_texture_size(t.kind) >> level;  // level l of a full chain is at most max >> l
  if (!t.proxy && (inner_w > level_max || inner_h > level_max || inner_d > level_max))
    return {GL_INVALID_VALUE, "the image is larger than the maximum texture size allows at level"};
  return GL_NO_ERROR;
}

bool tex_sub_image_may_read(GLenum target, int dims, GLint level, GLsizei width, GLsizei height, GLsizei depth,
                            GLenum format, GLenum type) {
  ImageTarget t;
  if (!image_target_of(target, dims, false, t) || texture_image_format_type_error(format, type) != GL_NO_ERROR)
    return false;
  if (level < 0 || level > max_texture_level(t.kind)) return false;
  // The region lies inside a level, whose sizes are at most max >> level.
  const int level_max = max_texture_size(t.kind) >> level;
  return width >= 0 && height >= 0 && depth >= 0 && width <= level_max && height <= level_max && depth <= level_max;
}

}  // namespace pineda
