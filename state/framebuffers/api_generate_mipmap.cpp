// glGenerateMipmap: the levels below the base level, from it (GL 3.0 3.8.8).
#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/framebuffers/framebuffer_object.h"
#include "state/textures/texture_target.h"

namespace pineda::gl {

void GenerateMipmap(Context& ctx, GLenum target) {
  TexTarget kind;
  // A rectangle has no mipmaps (ARB_texture_rectangle).
  if (!binding_target(target, kind) || kind == TexTarget::Rect)
    return ctx.record_error(GL_INVALID_ENUM, "target is not a mipmapped texture target");
  TextureObject& tex = ctx.textures.get_or_create(bound_name(ctx.texture_units[ctx.active_texture], kind), target);
  const int faces = kind == TexTarget::Cube ? kCubeFaces : 1;
  const size_t base = size_t(std::max(tex.params.base_level, 0));
  if (kind == TexTarget::Cube) {  // the faces' base levels must be cube complete
    const TextureLevelData* first = base < tex.levels.size() ? &tex.levels[base] : nullptr;
    for (int f = 0; f < faces; ++f) {
      const std::vector<TextureLevelData>& levels = tex.face_levels(f);
      const TextureLevelData* l = base < levels.size() ? &levels[base] : nullptr;
      if (!first || !l || l->width == 0 || l->width != l->height || l->width != first->width ||
          l->internal_format != first->internal_format)
        return ctx.record_error(GL_INVALID_OPERATION, "the cube map's base images are missing, not square or differ");
    }
  }
  resolve_rendered_textures(ctx);
  ctx.finish();
  for (int f = 0; f < faces; ++f) tex.generate_levels(int(base), f);
  refresh_framebuffer_views(ctx);  // attached lower levels may have been reallocated
}

}  // namespace pineda::gl
