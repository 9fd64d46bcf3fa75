// glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib: saved copies of the
// state groups of GL 1.1 spec Table 6.x.
#pragma once
#include <GL/gl.h>

#include <array>
#include <map>
#include <unordered_map>
#include <vector>

#include "raster/draw_state.h"
#include "raster/vertex_transform.h"
#include "state/multisample.h"
#include "state/color_index.h"
#include "state/draw_buffer_list.h"
#include "state/evaluators/evaluator.h"
#include "state/pixels/pixel_state.h"
#include "state/programs/program_state.h"
#include "state/stencil_faces.h"
#include "state/vertex_extras_state.h"
#include "state/textures/tex_env_state.h"
#include "state/textures/texture_object.h"

namespace pineda {

constexpr size_t kMaxAttribStackDepth = 16;
constexpr size_t kMaxClientAttribStackDepth = 16;

struct SavedTextureParams {
  GLuint name = 0;
  GLenum target = 0;
  TexParams params;
};

// Everything a glPushAttrib may save; glPopAttrib restores the groups of `mask` only.
struct AttribFrame {
  GLbitfield mask = 0;
  float accum_clear[4] = {0, 0, 0, 0};  // GL_ACCUM_BUFFER_BIT
  // current
  float current_color[4], current_normal[3];
  std::array<std::array<float, 4>, raster::kMaxTextureUnits> current_texcoord;
  bool current_edge_flag;
  std::array<std::array<float, 4>, kMaxVertexAttribs> current_generic;  // CURRENT_VERTEX_ATTRIB
  EvalAttribState eval;  // GL_EVAL_BIT; the map enables are also in GL_ENABLE_BIT
  ColorIndexState color_index;  // current index: CURRENT_BIT; clear index and mask: COLOR_BUFFER_BIT
  RasterPosition raster_pos;
  // pixel mode
  PixelMode pixel_mode;
  // rasterization, fragment, enables (kept whole; restored field by field)
  raster::DrawState draw_state;
  bool enable_cull, normalize, rescale_normal;
  bool program_point_size, program_two_side;  // GL_VERTEX_PROGRAM_POINT_SIZE, _TWO_SIDE (enable group)
  GLenum cull_face_mode, front_face, polygon_mode_front, polygon_mode_back, shade_model, matrix_mode;
  raster::Lighting lighting;
  GLenum color_material_face, color_material_mode;
  std::unordered_map<GLenum, bool> unrendered_caps;
  GLenum depth_func, alpha_func, stencil_func, stencil_fail, stencil_zfail, stencil_zpass;
  GLenum logic_op;
  GLuint stencil_value_mask, stencil_write_mask;
  StencilBackValues stencil_back_values;
  float clear_color[4];
  VertexExtrasState extras;
  MultisampleState multisample;  // GL_MULTISAMPLE_BIT
  double clear_depth;
  GLint clear_stencil;
  GLenum hints[7];
  raster::Viewport viewport;
  GLenum draw_buffer, read_buffer;
  ExtraDrawBuffers extra_draw_buffers;
  GLuint list_base;
  // texture
  struct Unit {
    bool enabled_1d, enabled_2d;
    GLuint bound_1d, bound_2d;
    TexEnvState env;
    SavedTextureParams params_1d, params_2d;
    bool enabled_3d, enabled_cube;
    GLuint bound_3d, bound_cube;
    SavedTextureParams params_3d, params_cube;
    bool enabled_rect;
    GLuint bound_rect;
    SavedTextureParams params_rect;
  };
  std::array<Unit, raster::kMaxTextureImageUnits> units;  // of the texture image units
  GLuint active_texture = 0;
};

}  // namespace pineda
