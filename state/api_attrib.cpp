// glPushAttrib/glPopAttrib, glPushClientAttrib/glPopClientAttrib.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/context.h"
#include "state/vertex_extras_attrib.h"

namespace pineda::gl {
namespace {

// The unrendered capabilities of one attribute group (GL 1.1 Table 6.x).
bool cap_in_group(GLenum cap, GLbitfield group) {
  switch (group) {
    case GL_POINT_BIT: return cap == GL_POINT_SMOOTH;
    case GL_LINE_BIT: return cap == GL_LINE_SMOOTH || cap == GL_LINE_STIPPLE;
    case GL_POLYGON_BIT: return cap == GL_POLYGON_SMOOTH || cap == GL_POLYGON_STIPPLE;
    case GL_FOG_BIT: return cap == GL_FOG;
    case GL_TRANSFORM_BIT: return cap >= GL_CLIP_PLANE0 && cap <= GL_CLIP_PLANE5;
    case GL_TEXTURE_BIT: return cap >= GL_TEXTURE_GEN_S && cap <= GL_TEXTURE_GEN_Q;
    case GL_COLOR_BUFFER_BIT: return cap == GL_INDEX_LOGIC_OP;
    case GL_ENABLE_BIT: return true;  // every capability is also an enable bit
    default: return false;
  }
}

void restore_caps(Context& ctx, const AttribFrame& f, GLbitfield group) {
  for (auto& [cap, on] : ctx.unrendered_caps)
    if (cap_in_group(cap, group)) on = false;
  for (const auto& [cap, on] : f.unrendered_caps)
    if (cap_in_group(cap, group)) ctx.unrendered_caps[cap] = on;
}

SavedTextureParams save_params(Context& ctx, GLuint name, GLenum target) {
  const TextureObject& t = ctx.textures.get_or_create(name, target);
  return SavedTextureParams{name, target, t.params};
}

void restore_params(Context& ctx, const SavedTextureParams& p) {
  // A texture deleted since the push is not brought back.
  if (p.name != 0 && !ctx.textures.find(p.name)) return;
  TextureObject& t = ctx.textures.get_or_create(p.name, p.target);
  t.params = p.params;
  t.changed();
}

AttribFrame save(Context& ctx, GLbitfield mask) {
  AttribFrame f;
  f.mask = mask;
  std::copy(ctx.current_color, ctx.current_color + 4, f.current_color);
  std::copy(ctx.current_normal, ctx.current_normal + 3, f.current_normal);
  for (int u = 0; u < raster::kMaxTextureUnits; ++u)
    std::copy(ctx.texture_units[u].current_texcoord, ctx.texture_units[u].current_texcoord + 4,
              f.current_texcoord[u].begin());
  f.current_edge_flag = ctx.current_edge_flag;
  f.current_generic = ctx.programs.current_attrib;
  f.color_index = ctx.color_index;
  f.eval = ctx.eval.attribs;
  f.raster_pos = ctx.raster_pos;
  f.pixel_mode = ctx.pixel_mode;
  f.draw_state = ctx.draw_state;
  std::copy(ctx.accum.clear_value, ctx.accum.clear_value + 4, f.accum_clear);
  for (raster::TextureUnit& unit : f.draw_state.texture_units) unit.image.reset();  // rebuilt per draw
  f.enable_cull = ctx.enable_cull;
  f.normalize = ctx.normalize;
  f.rescale_normal = ctx.rescale_normal;
  f.cull_face_mode = ctx.cull_face_mode;
  f.front_face = ctx.front_face;
  f.polygon_mode_front = ctx.polygon_mode_front;
  f.polygon_mode_back = ctx.polygon_mode_back;
  f.shade_model = ctx.shade_model;
  f.matrix_mode = ctx.matrix_mode;
  f.lighting = ctx.lighting;
  f.color_material_face = ctx.color_material_face;
  f.color_material_mode = ctx.color_material_mode;
  f.unrendered_caps = ctx.unrendered_caps;
  f.extras = ctx.extras;
  f.multisample = ctx.multisample;
  f.depth_func = ctx.depth_func;
  f.alpha_func = ctx.alpha_func;
  f.stencil_func = ctx.stencil_func;
  f.stencil_fail = ctx.stencil_fail;
  f.stencil_zfail = ctx.stencil_zfail;
  f.stencil_zpass = ctx.stencil_zpass;
  f.logic_op = ctx.logic_op;
  f.stencil_value_mask = ctx.stencil_value_mask;
  f.stencil_write_mask = ctx.stencil_write_mask;
  f.stencil_back_values = ctx.stencil_back_values;
  std::copy(ctx.clear_color, ctx.clear_color + 4, f.clear_color);
  f.clear_depth = ctx.clear_depth;
  f.clear_stencil = ctx.clear_stencil;
  f.hints[0] = ctx.hint_perspective;
  f.hints[1] = ctx.hint_point;
  f.hints[2] = ctx.hint_line;
  f.hints[3] = ctx.hint_polygon;
  f.hints[4] = ctx.hint_fog;
  f.hints[5] = ctx.hint_generate_mipmap;
  f.hints[6] = ctx.hint_texture_compression;
  f.viewport = ctx.viewport;
  f.draw_buffer = ctx.draw_buffer;
  f.extra_draw_buffers = ctx.extra_draw_buffers;
  f.read_buffer = ctx.read_buffer;
  f.list_base = ctx.list_base;
  f.program_point_size = ctx.programs.point_size_from_shader;
  f.program_two_side = ctx.programs.two_side;
  for (int u = 0; u < raster::kMaxTextureImageUnits; ++u) {  // enables: GL_ENABLE_BIT and GL_TEXTURE_BIT
    f.units[u].enabled_1d = ctx.texture_units[u].enabled_1d;
    f.units[u].enabled_2d = ctx.texture_units[u].enabled_2d;
    f.units[u].enabled_3d = ctx.texture_units[u].enabled_3d;
    f.units[u].enabled_cube = ctx.texture_units[u].enabled_cube;
    f.units[u].enabled_rect = ctx.texture_units[u].enabled_rect;
  }
  if (mask & GL_TEXTURE_BIT) {
    f.active_texture = ctx.active_texture;
    for (int u = 0; u < raster::kMaxTextureImageUnits; ++u) {
      const TextureUnitState& unit = ctx.texture_units[u];
      AttribFrame::Unit& s = f.units[u];
      s.bound_1d = unit.bound_1d;
      s.bound_2d = unit.bound_2d;
      s.env = unit.env;
      s.params_1d = save_params(ctx, unit.bound_1d, GL_TEXTURE_1D);
      s.params_2d = save_params(ctx, unit.bound_2d, GL_TEXTURE_2D);
      s.bound_3d = unit.bound_3d;
      s.bound_cube = unit.bound_cube;
      s.params_3d = save_params(ctx, unit.bound_3d, GL_TEXTURE_3D);
      s.params_cube = save_params(ctx, unit.bound_cube, GL_TEXTURE_CUBE_MAP);
      s.bound_rect = unit.bound_rect;
      s.params_rect = save_params(ctx, unit.bound_rect, GL_TEXTURE_RECTANGLE_ARB);
    }
  }
  return f;
}

void restore_enables(Context& ctx, const AttribFrame& f) {
  raster::DrawState& s = ctx.draw_state;
  const raster::DrawState& o = f.draw_state;
  s.alpha_test = o.alpha_test;
  s.blend = o.blend;
  for (size_t i = 0; i < s.more_targets.size(); ++i) s.more_targets[i].blend = o.more_targets[i].blend;
  s.logic_op_enabled = o.logic_op_enabled;
  s.depth_test = o.depth_test;
  s.dither = o.dither;
  s.scissor_test = o.scissor_test;
  s.stencil_test = o.stencil_test;
  s.offset_fill = o.offset_fill;
  s.offset_line = o.offset_line;
  s.offset_point = o.offset_point;
  s.point_smooth = o.point_smooth;
  s.point_params.sprite.enabled = o.point_params.sprite.enabled;
  s.line_smooth = o.line_smooth;
  ctx.enable_cull = f.enable_cull;
  ctx.lighting.enabled = f.lighting.enabled;
  for (int i = 0; i < raster::kMaxLights; ++i) ctx.lighting.lights[i].enabled = f.lighting.lights[i].enabled;
  ctx.lighting.color_material.enabled = f.lighting.color_material.enabled;
  ctx.normalize = f.normalize;
  ctx.rescale_normal = f.rescale_normal;
  ctx.programs.point_size_from_shader = f.program_point_size;
  ctx.programs.two_side = f.program_two_side;
  for (int u = 0; u < raster::kMaxTextureImageUnits; ++u) {
    ctx.texture_units[u].enabled_1d = f.units[u].enabled_1d;
    ctx.texture_units[u].enabled_2d = f.units[u].enabled_2d;
    ctx.texture_units[u].enabled_3d = f.units[u].enabled_3d;
    ctx.texture_units[u].enabled_cube = f.units[u].enabled_cube;
    ctx.texture_units[u].enabled_rect = f.units[u].enabled_rect;
  }
  restore_caps(ctx, f, GL_ENABLE_BIT);
  ctx.eval.attribs.map1_enabled = f.eval.map1_enabled;
  ctx.eval.attribs.map2_enabled = f.eval.map2_enabled;
  ctx.eval.attribs.auto_normal = f.eval.auto_normal;
}

void restore(Context& ctx, const AttribFrame& f) {
  raster::DrawState& s = ctx.draw_state;
  const raster::DrawState& o = f.draw_state;
  const GLbitfield m = f.mask;
  if (m & GL_CURRENT_BIT) {
    std::copy(f.current_color, f.current_color + 4, ctx.current_color);
    std::copy(f.current_normal, f.current_normal + 3, ctx.current_normal);
    for (int u = 0; u < raster::kMaxTextureUnits; ++u)
      std::copy(f.current_texcoord[u].begin(), f.current_texcoord[u].end(), ctx.texture_units[u].current_texcoord);
    ctx.current_edge_flag = f.current_edge_flag;
    ctx.programs.current_attrib = f.current_generic;
    ctx.color_index.current_index = f.color_index.current_index;
    ctx.raster_pos = f.raster_pos;
  }
  if (m & GL_POINT_BIT) {
    s.point_size = o.point_size;
    s.point_params = o.point_params;
    s.point_smooth = o.point_smooth;
    restore_caps(ctx, f, GL_POINT_BIT);
  }
  if (m & GL_LINE_BIT) {
    s.line_width = o.line_width;
    s.line_smooth = o.line_smooth;
    restore_caps(ctx, f, GL_LINE_BIT);
  }
  if (m & GL_POLYGON_BIT) {
    ctx.enable_cull = f.enable_cull;
    ctx.cull_face_mode = f.cull_face_mode;
    s.cull_front = o.cull_front;
    s.cull_back = o.cull_back;
    ctx.front_face = f.front_face;
    s.front_ccw = o.front_ccw;
    ctx.polygon_mode_front = f.polygon_mode_front;
    ctx.polygon_mode_back = f.polygon_mode_back;
    s.polygon_front = o.polygon_front;
    s.polygon_back = o.polygon_back;
    s.offset_factor = o.offset_factor;
    s.offset_units = o.offset_units;
    s.offset_fill = o.offset_fill;
    s.offset_line = o.offset_line;
    s.offset_point = o.offset_point;
    restore_caps(ctx, f, GL_POLYGON_BIT);
  }
  if (m & GL_PIXEL_MODE_BIT) {
    ctx.read_buffer = f.read_buffer;
    ctx.pixel_mode = f.pixel_mode;
  }
  if (m & GL_LIGHTING_BIT) {
    ctx.lighting = f.lighting;
    ctx.color_material_face = f.color_material_face;
    ctx.color_material_mode = f.color_material_mode;
    ctx.shade_model = f.shade_model;
    s.flat_shading = o.flat_shading;
  }
  if (m & GL_FOG_BIT) restore_caps(ctx, f, GL_FOG_BIT);
  if (m & GL_DEPTH_BUFFER_BIT) {
    s.depth_test = o.depth_test;
    ctx.depth_func = f.depth_func;
    s.depth_func = o.depth_func;
    ctx.clear_depth = f.clear_depth;
    s.depth_write = o.depth_write;
  }
  if (m & GL_STENCIL_BUFFER_BIT) {
    s.stencil_test = o.stencil_test;
    ctx.stencil_func = f.stencil_func;
    ctx.stencil_value_mask = f.stencil_value_mask;
    ctx.stencil_write_mask = f.stencil_write_mask;
    ctx.stencil_fail = f.stencil_fail;
    ctx.stencil_zfail = f.stencil_zfail;
    ctx.stencil_zpass = f.stencil_zpass;
    ctx.stencil_back_values = f.stencil_back_values;
    s.stencil_front = o.stencil_front;
    s.stencil_back = o.stencil_back;
    ctx.clear_stencil = f.clear_stencil;
  }
  if (m & GL_VIEWPORT_BIT) ctx.viewport = f.viewport;
  if (m & GL_TRANSFORM_BIT) {
    ctx.matrix_mode = f.matrix_mode;
    ctx.normalize = f.normalize;
    ctx.rescale_normal = f.rescale_normal;
    restore_caps(ctx, f, GL_TRANSFORM_BIT);
  }
  if (m & GL_ENABLE_BIT) restore_enables(ctx, f);
  if (m & GL_ACCUM_BUFFER_BIT) std::copy(f.accum_clear, f.accum_clear + 4, ctx.accum.clear_value);
  if (m & GL_COLOR_BUFFER_BIT) {
    s.alpha_test = o.alpha_test;
    ctx.alpha_func = f.alpha_func;
    s.alpha_func = o.alpha_func;
    s.alpha_ref = o.alpha_ref;
    s.blend = o.blend;
    s.blend_state = o.blend_state;
    s.dither = o.dither;
    s.logic_op_enabled = o.logic_op_enabled;
    ctx.logic_op = f.logic_op;
    s.logic_op = o.logic_op;
    ctx.draw_buffer = f.draw_buffer;
    ctx.extra_draw_buffers = f.extra_draw_buffers;
    s.color_write = o.color_write;
    s.more_targets = o.more_targets;  // their blend enables and colour masks
    std::copy(f.clear_color, f.clear_color + 4, ctx.clear_color);
    ctx.color_index.clear_index = f.color_index.clear_index;
    ctx.color_index.write_mask = f.color_index.write_mask;
    restore_caps(ctx, f, GL_COLOR_BUFFER_BIT);
  }
  if (m & GL_HINT_BIT) {
    ctx.hint_perspective = f.hints[0];
    ctx.hint_point = f.hints[1];
    ctx.hint_line = f.hints[2];
    ctx.hint_polygon = f.hints[3];
    ctx.hint_fog = f.hints[4];
    ctx.hint_generate_mipmap = f.hints[5];
    ctx.hint_texture_compression = f.hints[6];
  }
  if (m & GL_EVAL_BIT) ctx.eval.attribs = f.eval;
  if (m & GL_LIST_BIT) ctx.list_base = f.list_base;
  if (m & GL_TEXTURE_BIT) {
    for (int u = 0; u < raster::kMaxTextureImageUnits; ++u) {
      TextureUnitState& unit = ctx.texture_units[u];
      const AttribFrame::Unit& saved = f.units[u];
      unit.enabled_1d = saved.enabled_1d;
      unit.enabled_2d = saved.enabled_2d;
      unit.enabled_3d = saved.enabled_3d;
      unit.enabled_cube = saved.enabled_cube;
      unit.enabled_rect = saved.enabled_rect;
      unit.env = saved.env;
      // Bindings to textures deleted since the push fall back to the default texture.
      unit.bound_1d = saved.bound_1d == 0 || ctx.textures.find(saved.bound_1d) ? saved.bound_1d : 0;
      unit.bound_2d = saved.bound_2d == 0 || ctx.textures.find(saved.bound_2d) ? saved.bound_2d : 0;
      restore_params(ctx, saved.params_1d);
      restore_params(ctx, saved.params_2d);
      unit.bound_3d = saved.bound_3d == 0 || ctx.textures.find(saved.bound_3d) ? saved.bound_3d : 0;
      unit.bound_cube = saved.bound_cube == 0 || ctx.textures.find(saved.bound_cube) ? saved.bound_cube : 0;
      restore_params(ctx, saved.params_3d);
      restore_params(ctx, saved.params_cube);
      unit.bound_rect = saved.bound_rect == 0 || ctx.textures.find(saved.bound_rect) ? saved.bound_rect : 0;
      restore_params(ctx, saved.params_rect);
    }
    ctx.active_texture = f.active_texture;
    restore_caps(ctx, f, GL_TEXTURE_BIT);
  }
  if (m & GL_SCISSOR_BIT) {
    s.scissor_test = o.scissor_test;
    s.scissor = o.scissor;
  }
  restore_vertex_extras(ctx, f);
  restore_multisample(ctx, f);
}

}  // namespace

void PushAttrib(Context& ctx, GLbitfield mask) {
  if (ctx.attrib_stack.size() >= kMaxAttribStackDepth)
    return ctx.record_error(GL_STACK_OVERFLOW, "the attribute stack is full (GL_MAX_ATTRIB_STACK_DEPTH)");
  ctx.attrib_stack.push_back(save(ctx, mask));
}

void PopAttrib(Context& ctx) {
  if (ctx.attrib_stack.empty()) return ctx.record_error(GL_STACK_UNDERFLOW, "the attribute stack is empty");
  const AttribFrame frame = std::move(ctx.attrib_stack.back());
  ctx.attrib_stack.pop_back();
  restore(ctx, frame);
}

void PushClientAttrib(Context& ctx, GLbitfield mask) {
  if (ctx.client_attrib_stack.size() >= kMaxClientAttribStackDepth)
    return ctx.record_error(GL_STACK_OVERFLOW, "the client attribute stack is full (GL_MAX_CLIENT_ATTRIB_STACK_DEPTH)");
  ClientAttribFrame f;
  f.mask = mask;
  f.pack = ctx.pack;
  f.unpack = ctx.unpack;
  f.vertex_array_binding = ctx.vertex_array_objects.bound;
  f.arrays = save_vertex_array_group(ctx);
  f.array_buffer = ctx.buffers.array;
  f.client_active_texture = ctx.client_active_texture;
  ctx.client_attrib_stack.push_back(f);
}

void PopClientAttrib(Context& ctx) {
  if (ctx.client_attrib_stack.empty())
    return ctx.record_error(GL_STACK_UNDERFLOW, "the client attribute stack is empty");
  const ClientAttribFrame f = ctx.client_attrib_stack.back();
  ctx.client_attrib_stack.pop_back();
  if (f.mask & GL_CLIENT_PIXEL_STORE_BIT) {
    ctx.pack = f.pack;
    ctx.unpack = f.unpack;
  }
  if (f.mask & GL_CLIENT_VERTEX_ARRAY_BIT) {
    // The vertex array object bound at the push is bound again and given the saved arrays; one
    // deleted since is not brought back, and nothing of the group is restored (as Mesa does).
    const GLuint vao = f.vertex_array_binding;
    if (vao != 0 && !ctx.vertex_array_objects.names.generated(vao)) return;
    bind_vertex_array_object(ctx, vao);
    load_vertex_array_group(ctx, f.arrays);
    ctx.buffers.array = f.array_buffer;
    ctx.client_active_texture = f.client_active_texture;
  }
}

}  // namespace pineda::gl
