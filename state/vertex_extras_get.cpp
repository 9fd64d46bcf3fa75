// glGet* of fog, clip planes, stipple, texgen, secondary colour and their arrays.
#include "state/vertex_extras_get.h"

#include "state/context.h"

namespace pineda {
namespace {

GetValues colors(const float* c) { return {GetKind::Color, {c[0], c[1], c[2], c[3]}}; }

}  // namespace

bool query_vertex_extras(Context& ctx, unsigned pname, GetValues& out) {
  const raster::DrawState& s = ctx.draw_state;
  const VertexExtrasState& x = ctx.extras;
  switch (pname) {
    case GL_FOG_MODE: out = get_enums({double(x.fog_mode)}); return true;
    case GL_FOG_DENSITY: out = get_floats({s.fog.density}); return true;
    case GL_FOG_START: out = get_floats({s.fog.start}); return true;
    case GL_FOG_END: out = get_floats({s.fog.end}); return true;
    case GL_FOG_INDEX: out = get_floats({x.fog_index}); return true;
    case GL_FOG_COLOR: out = colors(s.fog.color); return true;
    case GL_FOG_COORD_SRC: out = get_enums({double(x.fog_coord_source)}); return true;
    case GL_CURRENT_FOG_COORD: out = get_floats({x.current_fog_coord}); return true;
    case GL_CURRENT_SECONDARY_COLOR: out = colors(x.current_secondary_color); return true;
    case GL_LIGHT_MODEL_COLOR_CONTROL:
      out = get_enums({double(ctx.lighting.separate_specular ? GL_SEPARATE_SPECULAR_COLOR : GL_SINGLE_COLOR)});
      return true;
    case GL_LINE_STIPPLE_PATTERN: out = get_ints({double(s.line_stipple.pattern)}); return true;
    case GL_LINE_STIPPLE_REPEAT: out = get_ints({double(s.line_stipple.factor)}); return true;
    case GL_FOG_COORD_ARRAY_TYPE: out = get_enums({double(ctx.fog_coord_array.type)}); return true;
    case GL_FOG_COORD_ARRAY_STRIDE: out = get_ints({double(ctx.fog_coord_array.stride)}); return true;
    case GL_SECONDARY_COLOR_ARRAY_SIZE: out = get_ints({double(ctx.secondary_color_array.size)}); return true;
    case GL_SECONDARY_COLOR_ARRAY_TYPE: out = get_enums({double(ctx.secondary_color_array.type)}); return true;
    case GL_SECONDARY_COLOR_ARRAY_STRIDE: out = get_ints({double(ctx.secondary_color_array.stride)}); return true;
    default: return false;
  }
}

}  // namespace pineda
