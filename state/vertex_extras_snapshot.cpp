#include "state/vertex_extras_snapshot.h"

#include "state/context.h"

namespace pineda {
namespace {

raster::TexGenMode texgen_mode(GLenum mode) {
  switch (mode) {
    case GL_OBJECT_LINEAR: return raster::TexGenMode::ObjectLinear;
    case GL_SPHERE_MAP: return raster::TexGenMode::SphereMap;
    case GL_NORMAL_MAP: return raster::TexGenMode::NormalMap;
    case GL_REFLECTION_MAP: return raster::TexGenMode::ReflectionMap;
    default: return raster::TexGenMode::EyeLinear;
  }
}

}  // namespace

bool texgen_needs_normal(const Context& ctx, int texture_units) {
  for (int u = 0; u < texture_units; ++u)
    for (const TexGenCoordState& c : ctx.extras.texgen[u])
      if (c.enabled && (c.mode == GL_SPHERE_MAP || c.mode == GL_NORMAL_MAP || c.mode == GL_REFLECTION_MAP)) return true;
  return false;
}

void snapshot_vertex_extras(Context& ctx, raster::Transform& t, int texture_units) {
  const VertexExtrasState& x = ctx.extras;
  raster::DrawState& s = ctx.draw_state;
  raster::VertexExtras& out = t.extras;

  // GL 1.5 section 3.9: with lighting the sum always applies (the secondary colour is the
  // separate specular colour, or zero); without it, GL_COLOR_SUM decides.
  s.color_sum = ctx.lighting.enabled ? ctx.lighting.separate_specular : x.color_sum;
  out.color_sum = s.color_sum;
  out.fog = s.fog.enabled;
  out.fog_from_coord = x.fog_coord_source == GL_FOG_COORD;

  s.clip_planes = 0;
  for (int i = 0; i < raster::kMaxClipPlanes; ++i) {
    if (!x.clip_plane_enabled[i]) continue;
    s.clip_planes |= 1u << i;
    out.clip_plane_eye[i] = glm::vec4(x.clip_planes[i]);
  }
  out.clip_planes = s.clip_planes;

  for (int u = 0; u < texture_units; ++u) {
    for (int i = 0; i < 4; ++i) {
      const TexGenCoordState& c = x.texgen[u][i];
      raster::TexGenCoord& g = out.texgen[u].coord[i];
      g.enabled = c.enabled;
      g.mode = texgen_mode(c.mode);
      g.object_plane = glm::vec4(c.object_plane);
      g.eye_plane = glm::vec4(c.eye_plane);
    }
  }
}

}  // namespace pineda
