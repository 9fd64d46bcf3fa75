// glGet of the raster position, pixel-transfer modes, zoom and pixel-map sizes.
#include "state/context.h"
#include "state/get_values.h"

namespace pineda {

bool query_pixel_state(Context& ctx, unsigned pname, GetValues& out) {
  const RasterPosition& rp = ctx.raster_pos;
  const PixelMode& m = ctx.pixel_mode;
  if (pname >= GL_PIXEL_MAP_I_TO_I_SIZE && pname <= GL_PIXEL_MAP_A_TO_A_SIZE) {
    out = get_ints({double(ctx.pixel_maps[GLenum(GL_PIXEL_MAP_I_TO_I + (pname - GL_PIXEL_MAP_I_TO_I_SIZE))].size())});
    return true;
  }
  switch (pname) {
    case GL_CURRENT_RASTER_POSITION:
      out = get_floats({rp.window[0], rp.window[1], rp.window[2], rp.window[3]});
      return true;
    case GL_CURRENT_RASTER_POSITION_VALID: out = get_bools({double(rp.valid)}); return true;
    case GL_CURRENT_RASTER_COLOR:
      out = {GetKind::Color, {rp.color[0], rp.color[1], rp.color[2], rp.color[3]}};
      return true;
    case GL_CURRENT_RASTER_SECONDARY_COLOR: {
      const float* c = rp.secondary_color;
      out = {GetKind::Color, {c[0], c[1], c[2], c[3]}};
      return true;
    }
    case GL_CURRENT_RASTER_INDEX: out = get_floats({1.0}); return true;  // no colour-index mode
    case GL_CURRENT_RASTER_TEXTURE_COORDS: {
      const float* t = rp.texcoord[ctx.active_texture];
      out = get_floats({t[0], t[1], t[2], t[3]});
      return true;
    }
    case GL_CURRENT_RASTER_DISTANCE: out = get_floats({rp.distance}); return true;
    case GL_MAP_COLOR: out = get_bools({double(m.map_color)}); return true;
    case GL_MAP_STENCIL: out = get_bools({double(m.map_stencil)}); return true;
    case GL_INDEX_SHIFT: out = get_ints({double(m.index_shift)}); return true;
    case GL_INDEX_OFFSET: out = get_ints({double(m.index_offset)}); return true;
    case GL_RED_SCALE: out = get_floats({m.scale[0]}); return true;
    case GL_GREEN_SCALE: out = get_floats({m.scale[1]}); return true;
    case GL_BLUE_SCALE: out = get_floats({m.scale[2]}); return true;
    case GL_ALPHA_SCALE: out = get_floats({m.scale[3]}); return true;
    case GL_RED_BIAS: out = get_floats({m.bias[0]}); return true;
    case GL_GREEN_BIAS: out = get_floats({m.bias[1]}); return true;
    case GL_BLUE_BIAS: out = get_floats({m.bias[2]}); return true;
    case GL_ALPHA_BIAS: out = get_floats({m.bias[3]}); return true;
    case GL_DEPTH_SCALE: out = get_floats({m.depth_scale}); return true;
    case GL_DEPTH_BIAS: out = get_floats({m.depth_bias}); return true;
    case GL_ZOOM_X: out = get_floats({m.zoom_x}); return true;
    case GL_ZOOM_Y: out = get_floats({m.zoom_y}); return true;
    default: return false;
  }
}

}  // namespace pineda
