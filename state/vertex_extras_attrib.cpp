#include "state/vertex_extras_attrib.h"

#include <algorithm>

#include "state/attrib_stack.h"
#include "state/context.h"

namespace pineda {
namespace {

void restore_enables(Context& ctx, const AttribFrame& f) {
  raster::DrawState& s = ctx.draw_state;
  const raster::DrawState& o = f.draw_state;
  VertexExtrasState& x = ctx.extras;
  s.fog.enabled = o.fog.enabled;
  s.line_stipple.enabled = o.line_stipple.enabled;
  s.polygon_stipple.enabled = o.polygon_stipple.enabled;
  x.color_sum = f.extras.color_sum;
  x.clip_plane_enabled = f.extras.clip_plane_enabled;
  for (int u = 0; u < raster::kMaxTextureUnits; ++u)
    for (int i = 0; i < 4; ++i) x.texgen[u][i].enabled = f.extras.texgen[u][i].enabled;
}

}  // namespace

void restore_vertex_extras(Context& ctx, const AttribFrame& f) {
  raster::DrawState& s = ctx.draw_state;
  const raster::DrawState& o = f.draw_state;
  VertexExtrasState& x = ctx.extras;
  const VertexExtrasState& saved = f.extras;
  const GLbitfield m = f.mask;
  if (m & GL_CURRENT_BIT) {
    x.current_fog_coord = saved.current_fog_coord;
    std::copy(saved.current_secondary_color, saved.current_secondary_color + 4, x.current_secondary_color);
  }
  if (m & GL_FOG_BIT) {
    s.fog = o.fog;
    x.fog_mode = saved.fog_mode;
    x.fog_coord_source = saved.fog_coord_source;
    x.fog_index = saved.fog_index;
    x.color_sum = saved.color_sum;
  }
  if (m & GL_LINE_BIT) s.line_stipple = o.line_stipple;
  if (m & GL_POLYGON_BIT) s.polygon_stipple.enabled = o.polygon_stipple.enabled;
  if (m & GL_POLYGON_STIPPLE_BIT) s.polygon_stipple.rows = o.polygon_stipple.rows;
  if (m & GL_TRANSFORM_BIT) {
    x.clip_planes = saved.clip_planes;
    x.clip_plane_enabled = saved.clip_plane_enabled;
  }
  if (m & GL_TEXTURE_BIT) x.texgen = saved.texgen;
  if (m & GL_ENABLE_BIT) restore_enables(ctx, f);
}

}  // namespace pineda
