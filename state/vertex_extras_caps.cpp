// The enables of fog, stipple, user clip planes, texgen and the colour sum.
#include "state/capabilities.h"
#include "state/context.h"

namespace pineda {

bool* vertex_extras_capability(Context& ctx, GLenum cap) {
  raster::DrawState& s = ctx.draw_state;
  VertexExtrasState& x = ctx.extras;
  if (cap >= GL_CLIP_PLANE0 && cap < GL_CLIP_PLANE0 + raster::kMaxClipPlanes) return &x.clip_plane_enabled[cap - GL_CLIP_PLANE0];
  if (cap >= GL_TEXTURE_GEN_S && cap <= GL_TEXTURE_GEN_Q)
    return ctx.fixed_function_texture_unit() ? &x.texgen[ctx.active_texture][cap - GL_TEXTURE_GEN_S].enabled : nullptr;
  switch (cap) {
    case GL_FOG: return &s.fog.enabled;
    case GL_LINE_STIPPLE: return &s.line_stipple.enabled;
    case GL_POLYGON_STIPPLE: return &s.polygon_stipple.enabled;
    case GL_COLOR_SUM: return &x.color_sum;
    default: return nullptr;
  }
}

bool* vertex_extras_client_capability(Context& ctx, GLenum array) {
  switch (array) {
    case GL_FOG_COORD_ARRAY: return &ctx.fog_coord_array.enabled;
    case GL_SECONDARY_COLOR_ARRAY: return &ctx.secondary_color_array.enabled;
    default: return nullptr;
  }
}

}  // namespace pineda
