// glEnable/glDisable/glIsEnabled and the client-array switches.
#include "glapi/gl_entry_points.h"
#include "state/capabilities.h"
#include "state/color_material.h"
#include "state/es1/es1_enums.h"
#include "state/es2/es2_rules.h"
#include "state/context.h"
#include "state/programs/program_get.h"

namespace pineda {
namespace {

bool is_unrendered_cap(GLenum cap) {
  switch (cap) {
    case GL_POLYGON_SMOOTH: case GL_INDEX_LOGIC_OP:
      return true;
    default:
      return false;
  }
}

}  // namespace

bool missing_texture_unit_state(const Context& ctx, GLenum pname) {
  if (ctx.es2() || ctx.fixed_function_texture_unit()) return false;
  switch (pname) {
    case GL_TEXTURE_1D: case GL_TEXTURE_2D: case GL_TEXTURE_3D: case GL_TEXTURE_CUBE_MAP: case GL_TEXTURE_RECTANGLE_ARB:
    case GL_TEXTURE_GEN_S: case GL_TEXTURE_GEN_T: case GL_TEXTURE_GEN_R: case GL_TEXTURE_GEN_Q:
    case GL_CURRENT_TEXTURE_COORDS: case GL_CURRENT_RASTER_TEXTURE_COORDS:
    case GL_TEXTURE_MATRIX: case GL_TRANSPOSE_TEXTURE_MATRIX: case GL_TEXTURE_STACK_DEPTH:
      return true;
    default:
      return false;
  }
}

bool* server_capability(Context& ctx, GLenum cap) {
  raster::DrawState& s = ctx.draw_state;
  if (ctx.es2() && !es2_capability(cap)) return nullptr;
  if (missing_texture_unit_state(ctx, cap)) return nullptr;
  if (cap >= GL_LIGHT0 && cap < GL_LIGHT0 + raster::kMaxLights) return &ctx.lighting.lights[cap - GL_LIGHT0].enabled;
  switch (cap) {
    case GL_ALPHA_TEST: return &s.alpha_test;
    case GL_BLEND: return &s.blend;
    case GL_COLOR_LOGIC_OP: return &s.logic_op_enabled;
    case GL_CULL_FACE: return &ctx.enable_cull;
    case GL_DEPTH_TEST: return &s.depth_test;
    case GL_DITHER: return &s.dither;
    case GL_SCISSOR_TEST: return &s.scissor_test;
    case GL_STENCIL_TEST: return &s.stencil_test;
    case GL_POINT_SMOOTH: return &s.point_smooth;
    case GL_LINE_SMOOTH: return &s.line_smooth;
    case GL_POINT_SPRITE: return &s.point_params.sprite.enabled;
    case GL_POLYGON_OFFSET_FILL: return &s.offset_fill;
    case GL_POLYGON_OFFSET_LINE: return &s.offset_line;
    case GL_POLYGON_OFFSET_POINT: return &s.offset_point;
    case GL_LIGHTING: return &ctx.lighting.enabled;
    case GL_COLOR_MATERIAL: return &ctx.lighting.color_material.enabled;
    case GL_NORMALIZE: return &ctx.normalize;
    case GL_RESCALE_NORMAL: return &ctx.rescale_normal;
    case GL_TEXTURE_1D: return &ctx.texture_units[ctx.active_texture].enabled_1d;
    case GL_TEXTURE_2D: return &ctx.texture_units[ctx.active_texture].enabled_2d;
    case GL_TEXTURE_3D: return &ctx.texture_units[ctx.active_texture].enabled_3d;
    case GL_TEXTURE_CUBE_MAP: return &ctx.texture_units[ctx.active_texture].enabled_cube;
    case GL_TEXTURE_RECTANGLE_ARB: return ctx.es1() ? nullptr : &ctx.texture_units[ctx.active_texture].enabled_rect;
    case GL_DEBUG_OUTPUT: return ctx.es1() ? nullptr : &ctx.debug.enabled;
    case GL_DEBUG_OUTPUT_SYNCHRONOUS: return ctx.es1() ? nullptr : &ctx.debug.synchronous;
    default:
      if (bool* flag = vertex_extras_capability(ctx, cap)) return flag;
      if (bool* flag = evaluator_capability(ctx.eval.attribs, cap)) return flag;
      if (bool* flag = multisample_capability(ctx, cap)) return flag;
      if (bool* flag = program_capability(ctx, cap)) return flag;
      if (is_unrendered_cap(cap)) return &ctx.unrendered_caps[cap];
      return nullptr;
  }
}

bool* client_capability(Context& ctx, GLenum array) {
  if (ctx.es2()) return nullptr;  // no client arrays but the generic ones
  switch (array) {
    case GL_VERTEX_ARRAY: return &ctx.vertex_array.enabled;
    case GL_COLOR_ARRAY: return &ctx.color_array.enabled;
    case GL_NORMAL_ARRAY: return &ctx.normal_array.enabled;
    case GL_TEXTURE_COORD_ARRAY: return &ctx.texture_units[ctx.client_active_texture].texcoord_array.enabled;
    case GL_INDEX_ARRAY: return &ctx.index_array.enabled;
    case GL_EDGE_FLAG_ARRAY: return &ctx.edge_flag_array.enabled;
    case GL_POINT_SIZE_ARRAY_OES: return ctx.es1() ? &ctx.point_size_array.enabled : nullptr;
    default: return vertex_extras_client_capability(ctx, array);
  }
}

}  // namespace pineda

namespace pineda::gl {
namespace {

// Mesa's compatibility profile, the tie-breaker, also takes the client arrays here (as
// glEnableClientState), and piglit relies on it; compiled into a list, they switch on replay.
void set_capability(Context& ctx, GLenum cap, bool value) {
  if (missing_texture_unit_state(ctx, cap))
    return ctx.record_error(GL_INVALID_OPERATION,
                            "cap is per texture unit and the active unit is above GL_MAX_TEXTURE_UNITS");
  bool* flag = server_capability(ctx, cap);
  if (!flag) flag = client_capability(ctx, cap);
  if (!flag)
    return ctx.record_error(GL_INVALID_ENUM, [cap] { return "cap " + hex_enum(cap) + " is not a capability"; });
  *flag = value;
  if (cap == GL_COLOR_MATERIAL) track_color_material(ctx);
  if (cap == GL_BLEND)  // every draw buffer's (GL 3.0 4.1.8; EXT_draw_buffers2 sets them one at a time)
    for (raster::DrawState::TargetWrite& t : ctx.draw_state.more_targets) t.blend = value;
}

void set_client_capability(Context& ctx, GLenum array, bool value) {
  bool* flag = client_capability(ctx, array);
  if (!flag) return ctx.record_error(GL_INVALID_ENUM, "array is not a client array capability");
  *flag = value;
}

}  // namespace

void Enable(Context& ctx, GLenum cap) { set_capability(ctx, cap, true); }
void Disable(Context& ctx, GLenum cap) { set_capability(ctx, cap, false); }

GLboolean IsEnabled(Context& ctx, GLenum cap) {
  if (missing_texture_unit_state(ctx, cap)) {
    ctx.record_error(GL_INVALID_OPERATION, "cap is per texture unit and the active unit is above GL_MAX_TEXTURE_UNITS");
    return GL_FALSE;
  }
  if (bool* flag = server_capability(ctx, cap)) return *flag ? GL_TRUE : GL_FALSE;
  if (bool* flag = client_capability(ctx, cap)) return *flag ? GL_TRUE : GL_FALSE;
  ctx.record_error(GL_INVALID_ENUM, [cap] { return "cap " + hex_enum(cap) + " is not a capability"; });
  return GL_FALSE;
}

void EnableClientState(Context& ctx, GLenum array) { set_client_capability(ctx, array, true); }
void DisableClientState(Context& ctx, GLenum array) { set_client_capability(ctx, array, false); }

}  // namespace pineda::gl
