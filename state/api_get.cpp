// glGet* for the state that exists, with GL's type conversions, and glGetString.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "glapi/gl_entry_points.h"
#include "state/blend_function.h"
#include "state/buffers/buffer_get.h"
#include "state/accum.h"
#include "state/capabilities.h"
#include "state/render_mode_get.h"
#include "state/es1/es1_enums.h"
#include "state/context.h"
#include "state/get_values.h"
#include "state/framebuffers/framebuffer_get.h"
#include "state/vertex_extras_get.h"
#include "state/limits.h"
#include "state/multisample.h"
#include "state/point_parameters.h"
#include "state/programs/program_get.h"
#include "state/stencil_faces.h"
#include "state/draw_buffer_list.h"

namespace pineda::gl {
namespace {

using Kind = GetKind;
using Values = GetValues;

Values ints(std::initializer_list<double> v) { return {Kind::Int, v}; }
Values enums(std::initializer_list<double> v) { return {Kind::Enum, v}; }
Values bools(std::initializer_list<double> v) { return {Kind::Bool, v}; }
Values floats(std::initializer_list<double> v) { return {Kind::Float, v}; }
Values colors(const float* c) { return {Kind::Color, {c[0], c[1], c[2], c[3]}}; }
Values matrix(const glm::dmat4& m) {
  Values r{Kind::Float, {}};
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) r.v.push_back(m[c][row]);
  return r;
}

enum class ArrayField { Size, Type, Stride };

const ClientArray* client_array(Context& ctx, GLenum pname, ArrayField& field) {
  struct Entry { GLenum size, type, stride; const ClientArray* array; };
  const Entry entries[] = {
      {GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE, &ctx.vertex_array},
      {GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE, &ctx.color_array},
      {0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE, &ctx.normal_array},
      {0, GL_INDEX_ARRAY_TYPE, GL_INDEX_ARRAY_STRIDE, &ctx.index_array},
      {GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE, GL_TEXTURE_COORD_ARRAY_STRIDE,
       &ctx.texture_units[ctx.client_active_texture].texcoord_array},
      {0, GL_POINT_SIZE_ARRAY_TYPE_OES, GL_POINT_SIZE_ARRAY_STRIDE_OES, ctx.es1() ? &ctx.point_size_array : nullptr},
  };
  for (const Entry& e : entries) {
    if (pname == e.size && e.size) field = ArrayField::Size;
    else if (pname == e.type) field = ArrayField::Type;
    else if (pname == e.stride) field = ArrayField::Stride;
    else continue;
    return e.array;
  }
  return nullptr;
}

bool query(Context& ctx, GLenum pname, Values& out) {
  const raster::DrawState& s = ctx.draw_state;
  const Drawable* d = ctx.draw_drawable();
  const int stencil_bits = d ? d->framebuffer.stencil.bits : 0;
  const TextureUnitState& unit = ctx.texture_units[ctx.active_texture];
  if (missing_texture_unit_state(ctx, pname)) return false;
  if (!ctx.es1() && query_es2(ctx, pname, out)) return true;
  if (ArrayField field; const ClientArray* a = client_array(ctx, pname, field)) {
    out = field == ArrayField::Type ? enums({double(a->type)})
                                    : ints({double(field == ArrayField::Size ? a->size : a->stride)});
    return true;
  }
  switch (pname) {
    case GL_CURRENT_COLOR: out = colors(ctx.current_color); return true;
    case GL_CURRENT_NORMAL:  // normals map to the int range as colours do (GL 1.1 spec 6.1.2)
      out = {Kind::Color, {ctx.current_normal[0], ctx.current_normal[1], ctx.current_normal[2]}};
      return true;
    case GL_CURRENT_TEXTURE_COORDS: {
      const float* t = unit.current_texcoord;
      out = floats({t[0], t[1], t[2], t[3]});
      return true;
    }
    case GL_EDGE_FLAG: out = bools({double(ctx.current_edge_flag)}); return true;
    case GL_COLOR_CLEAR_VALUE: out = colors(ctx.clear_color); return true;
    case GL_DEPTH_CLEAR_VALUE: out = {Kind::Color, {ctx.clear_depth}}; return true;
    case GL_STENCIL_CLEAR_VALUE: out = ints({double(ctx.clear_stencil)}); return true;
    case GL_DEPTH_RANGE: out = {Kind::Color, {ctx.viewport.near_z, ctx.viewport.far_z}}; return true;
    case GL_VIEWPORT: out = ints({double(ctx.viewport.x), double(ctx.viewport.y), double(ctx.viewport.width), double(ctx.viewport.height)}); return true;
    case GL_SCISSOR_BOX: out = ints({double(s.scissor.x), double(s.scissor.y), double(s.scissor.width), double(s.scissor.height)}); return true;
    case GL_MAX_VIEWPORT_DIMS: out = ints({kMaxViewportDim, kMaxViewportDim}); return true;
    case GL_MAX_TEXTURE_SIZE: out = ints({kMaxTextureSize}); return true;
    case GL_RESET_NOTIFICATION_STRATEGY_ARB:
      out = ints({double(ctx.attribs().lose_context_on_reset ? GL_LOSE_CONTEXT_ON_RESET_ARB : GL_NO_RESET_NOTIFICATION_ARB)});
      return true;
    case GL_CONTEXT_ROBUST_ACCESS: out = bools({double(ctx.attribs().robust_access)}); return true;
    case GL_MAX_3D_TEXTURE_SIZE: out = ints({kMax3DTextureSize}); return true;
    case GL_MAX_CUBE_MAP_TEXTURE_SIZE: out = ints({kMaxCubeMapTextureSize}); return true;
    case GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB: out = ints({kMaxRectangleTextureSize}); return true;
    case GL_MAX_MODELVIEW_STACK_DEPTH: out = ints({kMaxModelviewStackDepth}); return true;
    case GL_MAX_PROJECTION_STACK_DEPTH: out = ints({kMaxProjectionStackDepth}); return true;
    case GL_MAX_TEXTURE_STACK_DEPTH: out = ints({kMaxTextureStackDepth}); return true;
    case GL_MAX_LIGHTS: out = ints({raster::kMaxLights}); return true;
    case GL_MAX_TEXTURE_UNITS: out = ints({raster::kMaxTextureUnits}); return true;
    case GL_MAX_TEXTURE_LOD_BIAS: out = floats({kMaxTextureLodBias}); return true;
    case GL_ACTIVE_TEXTURE: out = enums({double(GL_TEXTURE0 + ctx.active_texture)}); return true;
    case GL_CLIENT_ACTIVE_TEXTURE: out = enums({double(GL_TEXTURE0 + ctx.client_active_texture)}); return true;
    case GL_MAX_CLIP_PLANES: out = ints({6}); return true;
    case GL_VERTEX_ARRAY_BINDING:  // GL_ARB_vertex_array_object (GL_VERTEX_ARRAY_BINDING_OES in ES 2.0)
      if (ctx.es1()) return false;
      out = ints({double(ctx.vertex_array_objects.bound)});
      return true;
    case GL_MAX_ATTRIB_STACK_DEPTH: out = ints({double(kMaxAttribStackDepth)}); return true;
    case GL_MAX_CLIENT_ATTRIB_STACK_DEPTH: out = ints({double(kMaxClientAttribStackDepth)}); return true;
    case GL_ATTRIB_STACK_DEPTH: out = ints({double(ctx.attrib_stack.size())}); return true;
    case GL_CLIENT_ATTRIB_STACK_DEPTH: out = ints({double(ctx.client_attrib_stack.size())}); return true;
    case GL_MAX_NAME_STACK_DEPTH: out = ints({64}); return true;
    case GL_MAX_LIST_NESTING: out = ints({kMaxListNesting}); return true;
    case GL_LIST_BASE: out = ints({double(ctx.list_base)}); return true;
    case GL_LIST_INDEX: out = ints({double(ctx.compilation.name)}); return true;
    case GL_LIST_MODE: out = enums({double(ctx.compiling_list() ? ctx.compilation.mode : 0)}); return true;
    case GL_MAX_EVAL_ORDER: out = ints({30}); return true;
    case GL_MAX_PIXEL_MAP_TABLE: out = ints({256}); return true;
    case GL_SUBPIXEL_BITS: out = ints({kSubpixelBits}); return true;
    case GL_RED_BITS: out = ints({double(d ? d->red_bits : 0)}); return true;
    case GL_GREEN_BITS: out = ints({double(d ? d->green_bits : 0)}); return true;
    case GL_BLUE_BITS: out = ints({double(d ? d->blue_bits : 0)}); return true;
    case GL_ALPHA_BITS: out = ints({double(d ? d->alpha_bits : 0)}); return true;
    case GL_DEPTH_BITS: out = ints({double(d ? d->framebuffer.depth.bits : 0)}); return true;
    case GL_STENCIL_BITS: out = ints({double(stencil_bits)}); return true;
    case GL_ACCUM_RED_BITS: case GL_ACCUM_GREEN_BITS: case GL_ACCUM_BLUE_BITS: case GL_ACCUM_ALPHA_BITS:
      out = ints({double(d && d->accum ? kAccumBits : 0)});
      return true;
    case GL_ACCUM_CLEAR_VALUE: out = colors(ctx.accum.clear_value); return true;
    case GL_INDEX_BITS: case GL_AUX_BUFFERS:
      out = ints({0});
      return true;
    case GL_RGBA_MODE: out = bools({1}); return true;
    case GL_INDEX_MODE: case GL_STEREO: out = bools({0}); return true;
    case GL_DOUBLEBUFFER: out = bools({double(d && d->double_buffered)}); return true;
    case GL_MATRIX_MODE: out = enums({double(ctx.matrix_mode)}); return true;
    case GL_MODELVIEW_MATRIX: out = matrix(ctx.modelview.top()); return true;
    case GL_PROJECTION_MATRIX: out = matrix(ctx.projection.top()); return true;
    case GL_TEXTURE_MATRIX: out = matrix(ctx.texture_matrix[ctx.active_texture].top()); return true;
    case GL_TRANSPOSE_MODELVIEW_MATRIX: out = matrix(glm::transpose(ctx.modelview.top())); return true;
    case GL_TRANSPOSE_PROJECTION_MATRIX: out = matrix(glm::transpose(ctx.projection.top())); return true;
    case GL_TRANSPOSE_TEXTURE_MATRIX:
      out = matrix(glm::transpose(ctx.texture_matrix[ctx.active_texture].top()));
      return true;
    case GL_MODELVIEW_STACK_DEPTH: out = ints({double(ctx.modelview.stack.size())}); return true;
    case GL_PROJECTION_STACK_DEPTH: out = ints({double(ctx.projection.stack.size())}); return true;
    case GL_TEXTURE_STACK_DEPTH: out = ints({double(ctx.texture_matrix[ctx.active_texture].stack.size())}); return true;
    case GL_POINT_SIZE: out = floats({s.point_size}); return true;
    case GL_POINT_SIZE_RANGE: out = floats({kPointSizeRange[0], kPointSizeRange[1]}); return true;
    // GL_POINT_SIZE_* are GL_SMOOTH_POINT_SIZE_* (and lines alike): antialiased sizes are kept to
    // 1/256 pixel; aliased ones are rounded to whole pixels.
    case GL_POINT_SIZE_GRANULARITY: out = floats({kSmoothSizeGranularity}); return true;
    case GL_ALIASED_POINT_SIZE_RANGE: out = floats({kPointSizeRange[0], kPointSizeRange[1]}); return true;
    case GL_LINE_WIDTH: out = floats({s.line_width}); return true;
    case GL_LINE_WIDTH_RANGE: out = floats({kLineWidthRange[0], kLineWidthRange[1]}); return true;
    case GL_LINE_WIDTH_GRANULARITY: out = floats({kSmoothSizeGranularity}); return true;
    case GL_ALIASED_LINE_WIDTH_RANGE: out = floats({kLineWidthRange[0], kLineWidthRange[1]}); return true;
    case GL_MAX_ELEMENTS_VERTICES: out = ints({kMaxElementsVertices}); return true;
    case GL_MAX_ELEMENTS_INDICES: out = ints({kMaxElementsIndices}); return true;
    case GL_CULL_FACE_MODE: out = enums({double(ctx.cull_face_mode)}); return true;
    case GL_FRONT_FACE: out = enums({double(ctx.front_face)}); return true;
    case GL_POLYGON_MODE: out = enums({double(ctx.polygon_mode_front), double(ctx.polygon_mode_back)}); return true;
    case GL_POLYGON_OFFSET_FACTOR: out = floats({s.offset_factor}); return true;
    case GL_POLYGON_OFFSET_UNITS: out = floats({s.offset_units}); return true;
    case GL_SHADE_MODEL: out = enums({double(ctx.shade_model)}); return true;
    case GL_DEPTH_FUNC: out = enums({double(ctx.depth_func)}); return true;
    case GL_DEPTH_WRITEMASK: out = bools({double(s.depth_write)}); return true;
    case GL_ALPHA_TEST_FUNC: out = enums({double(ctx.alpha_func)}); return true;
    case GL_ALPHA_TEST_REF: out = {Kind::Color, {s.alpha_ref}}; return true;
    case GL_STENCIL_FUNC: out = enums({double(ctx.stencil_func)}); return true;
    case GL_STENCIL_VALUE_MASK: out = ints({double(ctx.stencil_value_mask)}); return true;
    case GL_STENCIL_REF: out = ints({double(s.stencil_front.ref)}); return true;
    case GL_STENCIL_FAIL: out = enums({double(ctx.stencil_fail)}); return true;
    case GL_STENCIL_PASS_DEPTH_FAIL: out = enums({double(ctx.stencil_zfail)}); return true;
    case GL_STENCIL_PASS_DEPTH_PASS: out = enums({double(ctx.stencil_zpass)}); return true;
    case GL_STENCIL_WRITEMASK: out = ints({double(ctx.stencil_write_mask)}); return true;
    case GL_BLEND_SRC: case GL_BLEND_DST: case GL_BLEND_SRC_RGB: case GL_BLEND_DST_RGB:  // draw buffer 0's
    case GL_BLEND_SRC_ALPHA: case GL_BLEND_DST_ALPHA: case GL_BLEND_EQUATION: case GL_BLEND_EQUATION_ALPHA:
      out = enums({double(blend_function_enum(s.blend_state, pname))});
      return true;
    case GL_BLEND_COLOR: out = colors(s.blend_state.color); return true;
    case GL_LOGIC_OP_MODE: out = enums({double(ctx.logic_op)}); return true;
    case GL_COLOR_WRITEMASK:
      out = bools({double(s.color_write[0]), double(s.color_write[1]), double(s.color_write[2]), double(s.color_write[3])});
      return true;
    case GL_DRAW_BUFFER: out = enums({double(ctx.draw_buffer)}); return true;
    case GL_READ_BUFFER: out = enums({double(ctx.read_buffer)}); return true;
    case GL_PACK_ALIGNMENT: out = ints({double(ctx.pack.alignment)}); return true;
    case GL_PACK_ROW_LENGTH: out = ints({double(ctx.pack.row_length)}); return true;
    case GL_PACK_SKIP_ROWS: out = ints({double(ctx.pack.skip_rows)}); return true;
    case GL_PACK_SKIP_PIXELS: out = ints({double(ctx.pack.skip_pixels)}); return true;
    case GL_PACK_IMAGE_HEIGHT: out = ints({double(ctx.pack.image_height)}); return true;
    case GL_PACK_SKIP_IMAGES: out = ints({double(ctx.pack.skip_images)}); return true;
    case GL_PACK_SWAP_BYTES: out = bools({double(ctx.pack.swap_bytes)}); return true;
    case GL_PACK_LSB_FIRST: out = bools({double(ctx.pack.lsb_first)}); return true;
    case GL_UNPACK_ALIGNMENT: out = ints({double(ctx.unpack.alignment)}); return true;
    case GL_UNPACK_ROW_LENGTH: out = ints({double(ctx.unpack.row_length)}); return true;
    case GL_UNPACK_SKIP_ROWS: out = ints({double(ctx.unpack.skip_rows)}); return true;
    case GL_UNPACK_SKIP_PIXELS: out = ints({double(ctx.unpack.skip_pixels)}); return true;
    case GL_UNPACK_IMAGE_HEIGHT: out = ints({double(ctx.unpack.image_height)}); return true;
    case GL_UNPACK_SKIP_IMAGES: out = ints({double(ctx.unpack.skip_images)}); return true;
    case GL_UNPACK_SWAP_BYTES: out = bools({double(ctx.unpack.swap_bytes)}); return true;
    case GL_UNPACK_LSB_FIRST: out = bools({double(ctx.unpack.lsb_first)}); return true;
    case GL_EDGE_FLAG_ARRAY_STRIDE: out = ints({double(ctx.edge_flag_array.stride)}); return true;
    case GL_TEXTURE_BINDING_1D: out = ints({double(unit.bound_1d)}); return true;
    case GL_TEXTURE_BINDING_2D: out = ints({double(unit.bound_2d)}); return true;
    case GL_TEXTURE_BINDING_3D: out = ints({double(unit.bound_3d)}); return true;
    case GL_TEXTURE_BINDING_CUBE_MAP: out = ints({double(unit.bound_cube)}); return true;
    case GL_TEXTURE_BINDING_RECTANGLE_ARB: out = ints({double(unit.bound_rect)}); return true;
    case GL_SAMPLER_BINDING: out = ints({double(unit.sampler_name)}); return true;  // GL_ARB_sampler_objects
    case GL_PERSPECTIVE_CORRECTION_HINT: out = enums({double(ctx.hint_perspective)}); return true;
    case GL_POINT_SMOOTH_HINT: out = enums({double(ctx.hint_point)}); return true;
    case GL_LINE_SMOOTH_HINT: out = enums({double(ctx.hint_line)}); return true;
    case GL_POLYGON_SMOOTH_HINT: out = enums({double(ctx.hint_polygon)}); return true;
    case GL_FOG_HINT: out = enums({double(ctx.hint_fog)}); return true;
    case GL_GENERATE_MIPMAP_HINT: out = enums({double(ctx.hint_generate_mipmap)}); return true;
    case GL_TEXTURE_COMPRESSION_HINT: out = enums({double(ctx.hint_texture_compression)}); return true;
    case GL_LIGHT_MODEL_AMBIENT: {
      const glm::vec4& a = ctx.lighting.model_ambient;
      out = {Kind::Color, {a.r, a.g, a.b, a.a}};
      return true;
    }
    case GL_LIGHT_MODEL_LOCAL_VIEWER: out = bools({double(ctx.lighting.local_viewer)}); return true;
    case GL_LIGHT_MODEL_TWO_SIDE: out = bools({double(ctx.lighting.two_side)}); return true;
    case GL_COLOR_MATERIAL_FACE: out = enums({double(ctx.color_material_face)}); return true;
    case GL_COLOR_MATERIAL_PARAMETER: out = enums({double(ctx.color_material_mode)}); return true;
    default: break;
  }
  if (RenderModeValue rm; query_render_mode(ctx, pname, rm)) {
    out = rm.is_enum ? enums({double(rm.value)}) : ints({double(rm.value)});
    return true;
  }
  if (GLuint name; query_buffer_binding(ctx, pname, name)) {
    out = ints({double(name)});
    return true;
  }
  if (query_pixel_state(ctx, pname, out)) return true;
  if (query_vertex_extras(ctx, pname, out)) return true;
  if (query_multisample(ctx, pname, out)) return true;
  if (query_framebuffers(ctx, pname, out)) return true;
  if (query_color_index(ctx, pname, out)) return true;
  if (query_evaluator(ctx, pname, out)) return true;
  if (query_point_parameters(ctx, pname, out)) return true;
  if (query_stencil_back(ctx, pname, out)) return true;
  if (query_draw_buffers(ctx, pname, out)) return true;
  if (query_compressed_formats(ctx, pname, out)) return true;
  if (query_debug(ctx, pname, out)) return true;
  if (query_program_state(ctx, pname, out)) return true;
  if (ctx.es1() && query_es1(ctx, pname, out)) return true;
  // Every capability is also a boolean state.
  bool* flag = server_capability(ctx, pname);
  if (!flag) flag = client_capability(ctx, pname);
  if (!flag) return false;
  out = bools({double(*flag)});
  return true;
}

// GL 1.1 spec 6.1.2: colours become integers by a linear map of [-1, 1] onto the int range.
// NaN (state that GL stores as given, e.g. glPolygonOffset(NaN, 0)) reads as 0.
GLint to_int(Kind kind, double v) {
  if (std::isnan(v)) return 0;
  if (kind == Kind::Color) return static_cast<GLint>(std::clamp(v, -1.0, 1.0) * 2147483647.0);
  if (kind == Kind::Float) return static_cast<GLint>(std::clamp(std::round(v), -2147483648.0, 2147483647.0));
  return static_cast<GLint>(static_cast<int64_t>(v));
}

template <typename T, typename Convert>
void get(Context& ctx, GLenum pname, T* params, Convert convert) {
  Values values;
  if (missing_texture_unit_state(ctx, pname))
    return ctx.record_error(GL_INVALID_OPERATION,
                            "pname is per texture unit and the active unit is above GL_MAX_TEXTURE_UNITS");
  if (!query(ctx, pname, values)) return ctx.record_error(GL_INVALID_ENUM, "pname is not a state variable");
  if (!params) return;
  for (size_t i = 0; i < values.v.size(); ++i) params[i] = convert(values.kind, values.v[i]);
}

std::string version_string(const Context& ctx) {
  // OpenGL ES 1.1, 6.1.5: "OpenGL ES-CM 1.1" (the common profile), then vendor information.
  if (ctx.es1()) return std::string("OpenGL ES-CM 1.1 Pineda ") + PINEDA_VERSION_STRING;
  // OpenGL ES 2.0, 6.1.5: "OpenGL ES N.M", then vendor information.
  if (ctx.es2()) return std::string("OpenGL ES 2.0 Pineda ") + PINEDA_VERSION_STRING;
  return std::to_string(ctx.attribs().major) + "." + std::to_string(ctx.attribs().minor) + " Pineda " +
         PINEDA_VERSION_STRING;
}

}  // namespace

void GetBooleanv(Context& ctx, GLenum pname, GLboolean* params) {
  get(ctx, pname, params, [](Kind, double v) -> GLboolean { return v != 0.0 ? GL_TRUE : GL_FALSE; });
}
void GetIntegerv(Context& ctx, GLenum pname, GLint* params) { get(ctx, pname, params, to_int); }
void GetFloatv(Context& ctx, GLenum pname, GLfloat* params) {
  get(ctx, pname, params, [](Kind, double v) { return static_cast<GLfloat>(v); });
}
void GetDoublev(Context& ctx, GLenum pname, GLdouble* params) {
  get(ctx, pname, params, [](Kind, double v) { return v; });
}

const GLubyte* GetString(Context& ctx, GLenum name) {
  static const std::string kVendor = "Pineda";
  static const std::string kRenderer = "Pineda (software rasterizer)";
  static const std::string kExtensions =
      "GL_EXT_blend_color GL_EXT_blend_func_separate GL_EXT_blend_minmax GL_EXT_blend_subtract "
      "GL_EXT_blend_equation_separate "
      "GL_ARB_texture_non_power_of_two GL_EXT_texture_edge_clamp GL_SGIS_texture_edge_clamp GL_EXT_texture_env_add "
      "GL_ARB_vertex_buffer_object GL_ARB_occlusion_query GL_EXT_multi_draw_arrays GL_EXT_draw_range_elements "
      "GL_EXT_stencil_wrap GL_ATI_separate_stencil GL_ARB_draw_buffers GL_ATI_draw_buffers GL_EXT_draw_buffers2 "
      "GL_ARB_draw_buffers_blend GL_ARB_texture_storage "
      "GL_ARB_transpose_matrix GL_ARB_multisample GL_ARB_point_parameters GL_EXT_point_parameters GL_ARB_point_sprite "
      "GL_ARB_texture_compression GL_ARB_depth_texture GL_ARB_shadow GL_EXT_shadow_funcs "
      "GL_EXT_fog_coord GL_EXT_secondary_color GL_EXT_separate_specular_color "
      "GL_ARB_texture_border_clamp GL_ARB_texture_mirrored_repeat GL_ARB_multitexture GL_ARB_texture_env_add "
      "GL_ARB_texture_env_combine GL_ARB_texture_env_crossbar GL_ARB_texture_env_dot3 GL_EXT_bgra GL_ARB_window_pos GL_SGIS_generate_mipmap "
      "GL_SGIS_texture_lod GL_EXT_texture_lod_bias "
      "GL_EXT_texture3D GL_ARB_texture_cube_map GL_EXT_texture_cube_map GL_ARB_texture_rectangle GL_NV_texture_rectangle "
      "GL_EXT_texture_rectangle GL_EXT_vertex_array GL_KHR_debug "
      "GL_ARB_framebuffer_object GL_EXT_framebuffer_object GL_EXT_framebuffer_blit GL_EXT_framebuffer_multisample "
      "GL_EXT_packed_depth_stencil GL_ARB_depth_buffer_float "
      "GL_ARB_shader_objects GL_ARB_vertex_shader GL_ARB_fragment_shader GL_ARB_shading_language_100 "
      "GL_ARB_pixel_buffer_object GL_EXT_pixel_buffer_object GL_ARB_vertex_array_object GL_ARB_map_buffer_range GL_ARB_sampler_objects GL_ARB_copy_buffer "
      "GL_EXT_texture_sRGB GL_EXT_texture_sRGB_decode GL_EXT_texture_swizzle GL_ARB_texture_swizzle GL_ARB_robustness GL_KHR_robustness GL_ARB_ES2_compatibility ";  // a trailing space, as Mesa (programs split on it)
  switch (name) {
    case GL_VENDOR: return reinterpret_cast<const GLubyte*>(kVendor.c_str());
    case GL_RENDERER: return reinterpret_cast<const GLubyte*>(kRenderer.c_str());
    case GL_VERSION: {
      // Built once: a pointer returned earlier must stay valid.
      if (ctx.version_string.empty()) ctx.version_string = version_string(ctx);
      return reinterpret_cast<const GLubyte*>(ctx.version_string.c_str());
    }
    case GL_SHADING_LANGUAGE_VERSION:
      if (ctx.es1()) {
        ctx.record_error(GL_INVALID_ENUM, "OpenGL ES 1 has no shading language");
        return nullptr;
      }
      // OpenGL ES 2.0, 6.1.5: "OpenGL ES GLSL ES N.M", then vendor information.
      return reinterpret_cast<const GLubyte*>(ctx.es2() ? "OpenGL ES GLSL ES 1.00" : "1.20");
    case GL_EXTENSIONS:
      if (ctx.es2()) return reinterpret_cast<const GLubyte*>(glapi::kES2Extensions);
      return reinterpret_cast<const GLubyte*>(ctx.es1() ? glapi::kES1Extensions : kExtensions.c_str());
    default: ctx.record_error(GL_INVALID_ENUM, "name is not a string name"); return nullptr;
  }
}

GLenum GetError(Context& ctx) { return ctx.take_error(); }

// GL_ARB_robustness / GL_KHR_robustness / GL_EXT_robustness: a software context is never lost.
GLenum GetGraphicsResetStatusARB(Context&) { return GL_NO_ERROR; }

void Flush(Context& ctx) { ctx.finish_for_reading(); }
void Finish(Context& ctx) { ctx.finish_for_reading(); }

}  // namespace pineda::gl

namespace pineda {

bool query_get_values(Context& ctx, unsigned pname, GetValues& out) { return gl::query(ctx, pname, out); }

}  // namespace pineda
