// ARB_texture_storage: glTexStorage1D/2D/3D give a texture every level at once, in a sized
// internal format, and make its storage immutable (TEXTURE_IMMUTABLE_FORMAT): glTexImage*,
// glCopyTexImage* and glTexStorage* on it are INVALID_OPERATION afterwards, while the
// sub-image calls, glGenerateMipmap and rendering change its texels. A proxy target takes the
// levels when they fit and zeros them otherwise, without an error.
#include <algorithm>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/framebuffers/framebuffer_object.h"
#include "state/textures/tex_image_checks.h"
#include "state/textures/texture_format.h"
#include "state/textures/texture_target.h"

namespace pineda::gl {
namespace {

// A sized internal format: not 1-4, a base format or a generic compressed one (the spec's
// issue 27: INVALID_ENUM for those).
bool sized_format(GLenum f) {
  switch (f) {
    case 1: case 2: case 3: case 4:
    case GL_ALPHA: case GL_LUMINANCE: case GL_LUMINANCE_ALPHA: case GL_INTENSITY: case GL_RGB: case GL_RGBA:
    case GL_DEPTH_COMPONENT: case GL_DEPTH_STENCIL:
    case GL_SRGB: case GL_SRGB_ALPHA: case GL_SLUMINANCE: case GL_SLUMINANCE_ALPHA:
      return false;
    default:
      return stored_internal_format(GLint(f)) == GLint(f) && texture_format(GLint(f)).has_value();
  }
}

// The target of a glTexStorage call with `dims` dimensions: a binding target (TEXTURE_CUBE_MAP,
// not a face) or a proxy one.
bool storage_target(GLenum target, int dims, ImageTarget& out) {
  TexTarget kind;
  if (binding_target(target, kind)) {
    out = ImageTarget{kind, false, 0};
  } else if (!image_target(target, out) || !out.proxy) {
    return false;
  }
  return image_dimensions(out.kind) == dims;
}

int floor_log2(int v) {
  int l = 0;
  while (v >>= 1) ++l;
  return l;
}

// Level l of every face, each a level glTexImage would make with no data.
std::vector<TextureLevelData> level_chain(const TextureFormat& storage, GLenum internal_format, int levels, int w, int h,
                                          int d) {
  std::vector<TextureLevelData> chain(static_cast<size_t>(levels));
  for (int l = 0; l < levels; ++l) {
    TextureLevelData& level = chain[size_t(l)];
    level.width = std::max(1, w >> l);
    level.height = std::max(1, h >> l);
    level.depth = std::max(1, d >> l);
    level.internal_format = GLint(internal_format);
    level.base = storage.base;
    const size_t texels = size_t(level.width) * size_t(level.height) * size_t(level.depth);
    level.texels.assign(texels, 0u);
    if (storage.stencil) level.stencil.assign(texels, 0);
  }
  return chain;
}

void tex_storage(Context& ctx, int dims, GLenum target, GLsizei levels, GLenum internal_format, GLsizei width,
                 GLsizei height, GLsizei depth) {
  ImageTarget t;
  if (!storage_target(target, dims, t)) return ctx.record_error(GL_INVALID_ENUM, "target is not a target of the call");
  if (!sized_format(internal_format)) return ctx.record_error(GL_INVALID_ENUM, "internalformat is not a sized internal format");
  if (levels < 1 || width < 1 || height < 1 || depth < 1)
    return ctx.record_error(GL_INVALID_VALUE, "levels, width, height or depth is less than 1");
  if (t.kind == TexTarget::Cube && width != height)
    return ctx.record_error(GL_INVALID_VALUE, "a cube map's width and height differ");
  const int largest = std::max({width, dims >= 2 ? height : 1, dims == 3 ? depth : 1});
  if (levels > std::min(floor_log2(largest), max_texture_level(t.kind)) + 1)
    return ctx.record_error(GL_INVALID_OPERATION, "levels is more than a full mipmap chain of this size has");
  const TextureFormat storage = *texture_format(GLint(internal_format));
  const GLenum data_format = storage.stencil ? GL_DEPTH_STENCIL : storage.depth ? GL_DEPTH_COMPONENT : GL_RGBA;
  if (!depth_use_allowed(storage, t.kind, data_format))
    return ctx.record_error(GL_INVALID_OPERATION, "a depth format needs a 1D, 2D or rectangle target");
  const bool fits = largest <= max_texture_size(t.kind);
  const int faces = t.kind == TexTarget::Cube ? kCubeFaces : 1;
  if (t.proxy) {  // the levels when they fit, every level's state zero otherwise
    TextureObject& proxy = ctx.textures.proxy(t.kind);
    for (int f = 0; f < faces; ++f) {
      std::vector<TextureLevelData>& chain = proxy.face_levels(f);
      chain.assign(size_t(levels), TextureLevelData{});
      if (!fits) continue;
      for (int l = 0; l < levels; ++l)
        chain[size_t(l)] = TextureLevelData{std::max(1, width >> l), std::max(1, height >> l), std::max(1, depth >> l),
                                            0, GLint(internal_format), storage.base, {}, {}};
    }
    return;
  }
  if (!fits) return ctx.record_error(GL_INVALID_VALUE, "a size is above the maximum texture size");
  const GLuint name = bound_name(ctx.texture_units[ctx.active_texture], t.kind);
  if (name == 0) return ctx.record_error(GL_INVALID_OPERATION, "the default texture is bound to the target");
  resolve_rendered_textures(ctx);  // rendering queued into its levels lands first
  TextureObject& tex = ctx.textures.get_or_create(name, binding_enum(t.kind));
  if (tex.immutable_levels > 0) return ctx.record_error(GL_INVALID_OPERATION, "the texture's storage is immutable already");
  // Built aside: running out of memory leaves the texture as it was.
  std::vector<std::vector<TextureLevelData>> chains;
  for (int f = 0; f < faces; ++f)
    chains.push_back(level_chain(storage, internal_format, levels, width, dims >= 2 ? height : 1, dims == 3 ? depth : 1));
  for (int f = 0; f < faces; ++f) tex.face_levels(f) = std::move(chains[size_t(f)]);
  tex.make_immutable(levels);
}

}  // namespace

void TexStorage1D(Context& ctx, GLenum target, GLsizei levels, GLenum internalformat, GLsizei width) {
  tex_storage(ctx, 1, target, levels, internalformat, width, 1, 1);
}

void TexStorage2D(Context& ctx, GLenum target, GLsizei levels, GLenum internalformat, GLsizei width, GLsizei height) {
  tex_storage(ctx, 2, target, levels, internalformat, width, height, 1);
}

void TexStorage3D(Context& ctx, GLenum target, GLsizei levels, GLenum internalformat, GLsizei width, GLsizei height,
                  GLsizei depth) {
  tex_storage(ctx, 3, target, levels, internalformat, width, height, depth);
}

}  // namespace pineda::gl
