// Every queryable GL 1.5 state has the initial value of the spec's state tables 6.5-6.31
// (the imaging subset's tables 6.21-6.23 excepted: Pineda does not offer ARB_imaging), and
// the implementation-dependent values (6.27-6.30) are Pineda's. One row per value, queried
// with the command the table names.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

enum class Get {
  Float,      // glGetFloatv(pname)
  Integer,    // glGetIntegerv(pname)
  Boolean,    // glGetBooleanv(pname)
  Enabled,    // glIsEnabled(pname)
  Light,      // glGetLightfv(GL_LIGHT0 + index, pname)
  Material,   // glGetMaterialfv(target, pname)
  TexEnv,     // glGetTexEnvfv(target, pname)
  TexGen,     // glGetTexGenfv(target, pname)
  TexParam,   // glGetTexParameterfv(target, pname)
  TexLevel,   // glGetTexLevelParameterfv(target, index, pname)
  ClipPlane,  // glGetClipPlane(GL_CLIP_PLANE0 + index)
  Pointer,    // glGetPointerv(pname), as an integer
  Map,        // glGetMapfv(target, pname)
  Query,      // glGetQueryiv(target, pname)
  Buffer,     // glGetBufferParameteriv(target, pname) of a new buffer object
  Stipple,    // glGetPolygonStipple: 128 bytes
};

struct Row {
  Get get;
  GLenum target;
  GLenum pname;
  int index;
  std::vector<double> expected;
  int unit = 0;  // the active (and client active) texture unit while querying
  const char* name = "";
};

#define ROW(get, target, pname, index, ...) Row{Get::get, target, pname, index, {__VA_ARGS__}, 0, #pname}
#define F(pname, ...) ROW(Float, 0, pname, 0, __VA_ARGS__)
#define I(pname, ...) ROW(Integer, 0, pname, 0, __VA_ARGS__)
#define B(pname, ...) ROW(Boolean, 0, pname, 0, __VA_ARGS__)
#define OFF(pname) ROW(Enabled, 0, pname, 0, 0)
#define ON(pname) ROW(Enabled, 0, pname, 0, 1)

constexpr double kOnes = -1.0;  // an all-ones mask read as a signed integer

std::vector<Row> initial_state_rows() {
  std::vector<Row> rows = {
      // 6.5 Current values and associated data
      F(GL_CURRENT_COLOR, 1, 1, 1, 1),
      F(GL_CURRENT_SECONDARY_COLOR, 0, 0, 0, 1),
      F(GL_CURRENT_INDEX, 1),
      F(GL_CURRENT_TEXTURE_COORDS, 0, 0, 0, 1),
      F(GL_CURRENT_NORMAL, 0, 0, 1),
      F(GL_CURRENT_FOG_COORD, 0),
      F(GL_CURRENT_RASTER_POSITION, 0, 0, 0, 1),
      F(GL_CURRENT_RASTER_DISTANCE, 0),
      F(GL_CURRENT_RASTER_COLOR, 1, 1, 1, 1),
      F(GL_CURRENT_RASTER_INDEX, 1),
      F(GL_CURRENT_RASTER_TEXTURE_COORDS, 0, 0, 0, 1),
      B(GL_CURRENT_RASTER_POSITION_VALID, 1),
      B(GL_EDGE_FLAG, 1),
      // 6.6 Vertex array data
      I(GL_CLIENT_ACTIVE_TEXTURE, GL_TEXTURE0),
      OFF(GL_VERTEX_ARRAY), I(GL_VERTEX_ARRAY_SIZE, 4), I(GL_VERTEX_ARRAY_TYPE, GL_FLOAT),
      I(GL_VERTEX_ARRAY_STRIDE, 0), ROW(Pointer, 0, GL_VERTEX_ARRAY_POINTER, 0, 0),
      OFF(GL_NORMAL_ARRAY), I(GL_NORMAL_ARRAY_TYPE, GL_FLOAT), I(GL_NORMAL_ARRAY_STRIDE, 0),
      ROW(Pointer, 0, GL_NORMAL_ARRAY_POINTER, 0, 0),
      OFF(GL_FOG_COORD_ARRAY), I(GL_FOG_COORD_ARRAY_TYPE, GL_FLOAT), I(GL_FOG_COORD_ARRAY_STRIDE, 0),
      ROW(Pointer, 0, GL_FOG_COORD_ARRAY_POINTER, 0, 0),
      OFF(GL_COLOR_ARRAY), I(GL_COLOR_ARRAY_SIZE, 4), I(GL_COLOR_ARRAY_TYPE, GL_FLOAT), I(GL_COLOR_ARRAY_STRIDE, 0),
      ROW(Pointer, 0, GL_COLOR_ARRAY_POINTER, 0, 0),
      OFF(GL_SECONDARY_COLOR_ARRAY), I(GL_SECONDARY_COLOR_ARRAY_SIZE, 3),
      I(GL_SECONDARY_COLOR_ARRAY_TYPE, GL_FLOAT), I(GL_SECONDARY_COLOR_ARRAY_STRIDE, 0),
      ROW(Pointer, 0, GL_SECONDARY_COLOR_ARRAY_POINTER, 0, 0),
      OFF(GL_INDEX_ARRAY), I(GL_INDEX_ARRAY_TYPE, GL_FLOAT), I(GL_INDEX_ARRAY_STRIDE, 0),
      ROW(Pointer, 0, GL_INDEX_ARRAY_POINTER, 0, 0),
      OFF(GL_TEXTURE_COORD_ARRAY), I(GL_TEXTURE_COORD_ARRAY_SIZE, 4), I(GL_TEXTURE_COORD_ARRAY_TYPE, GL_FLOAT),
      I(GL_TEXTURE_COORD_ARRAY_STRIDE, 0), ROW(Pointer, 0, GL_TEXTURE_COORD_ARRAY_POINTER, 0, 0),
      OFF(GL_EDGE_FLAG_ARRAY), I(GL_EDGE_FLAG_ARRAY_STRIDE, 0), ROW(Pointer, 0, GL_EDGE_FLAG_ARRAY_POINTER, 0, 0),
      // 6.7 Vertex buffer objects
      I(GL_ARRAY_BUFFER_BINDING, 0), I(GL_VERTEX_ARRAY_BUFFER_BINDING, 0), I(GL_NORMAL_ARRAY_BUFFER_BINDING, 0),
      I(GL_COLOR_ARRAY_BUFFER_BINDING, 0), I(GL_INDEX_ARRAY_BUFFER_BINDING, 0),
      I(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, 0), I(GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, 0),
      I(GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, 0), I(GL_FOG_COORD_ARRAY_BUFFER_BINDING, 0),
      I(GL_ELEMENT_ARRAY_BUFFER_BINDING, 0),
      ROW(Buffer, GL_ARRAY_BUFFER, GL_BUFFER_SIZE, 0, 0), ROW(Buffer, GL_ARRAY_BUFFER, GL_BUFFER_USAGE, 0, GL_STATIC_DRAW),
      ROW(Buffer, GL_ARRAY_BUFFER, GL_BUFFER_ACCESS, 0, GL_READ_WRITE),
      ROW(Buffer, GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, 0, GL_FALSE),
      // 6.8 Transformation state
      F(GL_MODELVIEW_MATRIX, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),
      F(GL_PROJECTION_MATRIX, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),
      F(GL_TEXTURE_MATRIX, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),
      F(GL_TRANSPOSE_MODELVIEW_MATRIX, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),
      I(GL_VIEWPORT, 0, 0, 40, 24), F(GL_DEPTH_RANGE, 0, 1),
      I(GL_MODELVIEW_STACK_DEPTH, 1), I(GL_PROJECTION_STACK_DEPTH, 1), I(GL_TEXTURE_STACK_DEPTH, 1),
      I(GL_MATRIX_MODE, GL_MODELVIEW), OFF(GL_NORMALIZE), OFF(GL_RESCALE_NORMAL),
      // 6.9 Coloring
      F(GL_FOG_COLOR, 0, 0, 0, 0), F(GL_FOG_INDEX, 0), F(GL_FOG_DENSITY, 1), F(GL_FOG_START, 0), F(GL_FOG_END, 1),
      I(GL_FOG_MODE, GL_EXP), OFF(GL_FOG), I(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH), OFF(GL_COLOR_SUM),
      I(GL_SHADE_MODEL, GL_SMOOTH),
      // 6.10 Lighting
      OFF(GL_LIGHTING), OFF(GL_COLOR_MATERIAL), I(GL_COLOR_MATERIAL_PARAMETER, GL_AMBIENT_AND_DIFFUSE),
      I(GL_COLOR_MATERIAL_FACE, GL_FRONT_AND_BACK), F(GL_LIGHT_MODEL_AMBIENT, 0.2f, 0.2f, 0.2f, 1),
      B(GL_LIGHT_MODEL_LOCAL_VIEWER, 0), B(GL_LIGHT_MODEL_TWO_SIDE, 0),
      I(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SINGLE_COLOR),
      // 6.12 Rasterization
      F(GL_POINT_SIZE, 1), OFF(GL_POINT_SMOOTH), F(GL_POINT_SIZE_MIN, 0), F(GL_POINT_SIZE_MAX, 255),
      F(GL_POINT_FADE_THRESHOLD_SIZE, 1), F(GL_POINT_DISTANCE_ATTENUATION, 1, 0, 0),
      F(GL_LINE_WIDTH, 1), OFF(GL_LINE_SMOOTH), I(GL_LINE_STIPPLE_PATTERN, 0xffff), I(GL_LINE_STIPPLE_REPEAT, 1),
      OFF(GL_LINE_STIPPLE), OFF(GL_CULL_FACE), I(GL_CULL_FACE_MODE, GL_BACK), I(GL_FRONT_FACE, GL_CCW),
      OFF(GL_POLYGON_SMOOTH), I(GL_POLYGON_MODE, GL_FILL, GL_FILL), F(GL_POLYGON_OFFSET_FACTOR, 0),
      F(GL_POLYGON_OFFSET_UNITS, 0), OFF(GL_POLYGON_OFFSET_POINT), OFF(GL_POLYGON_OFFSET_LINE),
      OFF(GL_POLYGON_OFFSET_FILL), OFF(GL_POLYGON_STIPPLE),
      // 6.13 Multisampling
      ON(GL_MULTISAMPLE), OFF(GL_SAMPLE_ALPHA_TO_COVERAGE), OFF(GL_SAMPLE_ALPHA_TO_ONE), OFF(GL_SAMPLE_COVERAGE),
      F(GL_SAMPLE_COVERAGE_VALUE, 1), B(GL_SAMPLE_COVERAGE_INVERT, 0),
      // 6.14 Textures (per unit): the unit loop below repeats these for every unit
      // 6.15 Textures (per object)
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0, 0, 0, 0, 0),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, 0, GL_NEAREST_MIPMAP_LINEAR),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, 0, GL_LINEAR),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, 0, GL_REPEAT),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, 0, GL_REPEAT),
      ROW(TexParam, GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, 0, GL_REPEAT),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 0, 1),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 0, -1000),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 0, 1000),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0, 0),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0, 1000),
      ROW(TexParam, GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, 0, GL_LUMINANCE),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, 0, GL_NONE),
      ROW(TexParam, GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, 0, GL_LEQUAL),
      ROW(TexParam, GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 0, GL_FALSE),
      ROW(TexParam, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, 0, GL_NEAREST_MIPMAP_LINEAR),
      ROW(TexParam, GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, 0, GL_REPEAT),
      // ARB_texture_rectangle: no mipmaps and no repeating
      ROW(TexParam, GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MIN_FILTER, 0, GL_LINEAR),
      ROW(TexParam, GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_MAG_FILTER, 0, GL_LINEAR),
      ROW(TexParam, GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, 0, GL_CLAMP_TO_EDGE),
      ROW(TexParam, GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_T, 0, GL_CLAMP_TO_EDGE),
      ROW(TexParam, GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_R, 0, GL_CLAMP_TO_EDGE),
      ROW(TexParam, GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_BASE_LEVEL, 0, 0),
      // 6.16 Textures (per image)
      ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_WIDTH, 0, 0), ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_HEIGHT, 0, 0),
      ROW(TexLevel, GL_TEXTURE_3D, GL_TEXTURE_DEPTH, 0, 0), ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_BORDER, 0, 0),
      ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_INTERNAL_FORMAT, 0, 1),
      ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_RED_SIZE, 0, 0), ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_GREEN_SIZE, 0, 0),
      ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_BLUE_SIZE, 0, 0), ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_ALPHA_SIZE, 0, 0),
      ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_LUMINANCE_SIZE, 0, 0),
      ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_INTENSITY_SIZE, 0, 0),
      ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_DEPTH_SIZE, 0, 0),
      ROW(TexLevel, GL_TEXTURE_2D, GL_TEXTURE_COMPRESSED, 0, GL_FALSE),
      ROW(TexLevel, GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_WIDTH, 0, 0),
      ROW(TexLevel, GL_TEXTURE_1D, GL_TEXTURE_INTERNAL_FORMAT, 0, 1),
      ROW(TexLevel, GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WIDTH, 0, 0),
      ROW(TexLevel, GL_PROXY_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_HEIGHT, 0, 0),
      // 6.17 Texture environment and generation: the unit loop below
      I(GL_ACTIVE_TEXTURE, GL_TEXTURE0),
      // 6.18 Pixel operations
      OFF(GL_SCISSOR_TEST), I(GL_SCISSOR_BOX, 0, 0, 40, 24), OFF(GL_ALPHA_TEST), I(GL_ALPHA_TEST_FUNC, GL_ALWAYS),
      F(GL_ALPHA_TEST_REF, 0), OFF(GL_STENCIL_TEST), I(GL_STENCIL_FUNC, GL_ALWAYS), I(GL_STENCIL_VALUE_MASK, kOnes),
      I(GL_STENCIL_REF, 0), I(GL_STENCIL_FAIL, GL_KEEP), I(GL_STENCIL_PASS_DEPTH_FAIL, GL_KEEP),
      I(GL_STENCIL_PASS_DEPTH_PASS, GL_KEEP), OFF(GL_DEPTH_TEST), I(GL_DEPTH_FUNC, GL_LESS), OFF(GL_BLEND),
      I(GL_BLEND_SRC_RGB, GL_ONE), I(GL_BLEND_SRC_ALPHA, GL_ONE), I(GL_BLEND_DST_RGB, GL_ZERO),
      I(GL_BLEND_DST_ALPHA, GL_ZERO), I(GL_BLEND_SRC, GL_ONE), I(GL_BLEND_DST, GL_ZERO),
      I(GL_BLEND_EQUATION, GL_FUNC_ADD), F(GL_BLEND_COLOR, 0, 0, 0, 0), ON(GL_DITHER), OFF(GL_INDEX_LOGIC_OP),
      OFF(GL_COLOR_LOGIC_OP), I(GL_LOGIC_OP_MODE, GL_COPY),
      // 6.19 Framebuffer control
      I(GL_DRAW_BUFFER, GL_FRONT), I(GL_INDEX_WRITEMASK, kOnes), B(GL_COLOR_WRITEMASK, 1, 1, 1, 1),
      B(GL_DEPTH_WRITEMASK, 1), I(GL_STENCIL_WRITEMASK, kOnes), F(GL_COLOR_CLEAR_VALUE, 0, 0, 0, 0),
      F(GL_INDEX_CLEAR_VALUE, 0), F(GL_DEPTH_CLEAR_VALUE, 1), I(GL_STENCIL_CLEAR_VALUE, 0),
      F(GL_ACCUM_CLEAR_VALUE, 0, 0, 0, 0),
      // 6.20 Pixels
      B(GL_UNPACK_SWAP_BYTES, 0), B(GL_UNPACK_LSB_FIRST, 0), I(GL_UNPACK_IMAGE_HEIGHT, 0), I(GL_UNPACK_SKIP_IMAGES, 0),
      I(GL_UNPACK_ROW_LENGTH, 0), I(GL_UNPACK_SKIP_ROWS, 0), I(GL_UNPACK_SKIP_PIXELS, 0), I(GL_UNPACK_ALIGNMENT, 4),
      B(GL_PACK_SWAP_BYTES, 0), B(GL_PACK_LSB_FIRST, 0), I(GL_PACK_IMAGE_HEIGHT, 0), I(GL_PACK_SKIP_IMAGES, 0),
      I(GL_PACK_ROW_LENGTH, 0), I(GL_PACK_SKIP_ROWS, 0), I(GL_PACK_SKIP_PIXELS, 0), I(GL_PACK_ALIGNMENT, 4),
      B(GL_MAP_COLOR, 0), B(GL_MAP_STENCIL, 0), I(GL_INDEX_SHIFT, 0), I(GL_INDEX_OFFSET, 0), F(GL_RED_SCALE, 1),
      F(GL_GREEN_SCALE, 1), F(GL_BLUE_SCALE, 1), F(GL_ALPHA_SCALE, 1), F(GL_DEPTH_SCALE, 1), F(GL_RED_BIAS, 0),
      F(GL_GREEN_BIAS, 0), F(GL_BLUE_BIAS, 0), F(GL_ALPHA_BIAS, 0), F(GL_DEPTH_BIAS, 0),
      // 6.24 Pixels (cont.)
      F(GL_ZOOM_X, 1), F(GL_ZOOM_Y, 1), I(GL_PIXEL_MAP_I_TO_I_SIZE, 1), I(GL_PIXEL_MAP_S_TO_S_SIZE, 1),
      I(GL_PIXEL_MAP_I_TO_R_SIZE, 1), I(GL_PIXEL_MAP_I_TO_G_SIZE, 1), I(GL_PIXEL_MAP_I_TO_B_SIZE, 1),
      I(GL_PIXEL_MAP_I_TO_A_SIZE, 1), I(GL_PIXEL_MAP_R_TO_R_SIZE, 1), I(GL_PIXEL_MAP_G_TO_G_SIZE, 1),
      I(GL_PIXEL_MAP_B_TO_B_SIZE, 1), I(GL_PIXEL_MAP_A_TO_A_SIZE, 1), I(GL_READ_BUFFER, GL_FRONT),
      // 6.25 Evaluators
      ROW(Map, GL_MAP1_VERTEX_3, GL_ORDER, 0, 1), ROW(Map, GL_MAP1_VERTEX_3, GL_COEFF, 0, 0, 0, 0),
      ROW(Map, GL_MAP1_VERTEX_4, GL_COEFF, 0, 0, 0, 0, 1), ROW(Map, GL_MAP1_INDEX, GL_COEFF, 0, 1),
      ROW(Map, GL_MAP1_COLOR_4, GL_COEFF, 0, 1, 1, 1, 1), ROW(Map, GL_MAP1_NORMAL, GL_COEFF, 0, 0, 0, 1),
      ROW(Map, GL_MAP1_TEXTURE_COORD_1, GL_COEFF, 0, 0), ROW(Map, GL_MAP1_TEXTURE_COORD_2, GL_COEFF, 0, 0, 0),
      ROW(Map, GL_MAP1_TEXTURE_COORD_3, GL_COEFF, 0, 0, 0, 0),
      ROW(Map, GL_MAP1_TEXTURE_COORD_4, GL_COEFF, 0, 0, 0, 0, 1), ROW(Map, GL_MAP1_VERTEX_3, GL_DOMAIN, 0, 0, 1),
      ROW(Map, GL_MAP2_VERTEX_3, GL_ORDER, 0, 1, 1), ROW(Map, GL_MAP2_VERTEX_4, GL_COEFF, 0, 0, 0, 0, 1),
      ROW(Map, GL_MAP2_COLOR_4, GL_COEFF, 0, 1, 1, 1, 1), ROW(Map, GL_MAP2_VERTEX_3, GL_DOMAIN, 0, 0, 1, 0, 1),
      OFF(GL_MAP1_VERTEX_3), OFF(GL_MAP1_VERTEX_4), OFF(GL_MAP1_INDEX), OFF(GL_MAP1_COLOR_4), OFF(GL_MAP1_NORMAL),
      OFF(GL_MAP1_TEXTURE_COORD_1), OFF(GL_MAP1_TEXTURE_COORD_4), OFF(GL_MAP2_VERTEX_3), OFF(GL_MAP2_VERTEX_4),
      OFF(GL_MAP2_INDEX), OFF(GL_MAP2_COLOR_4), OFF(GL_MAP2_NORMAL), OFF(GL_MAP2_TEXTURE_COORD_1),
      OFF(GL_MAP2_TEXTURE_COORD_4), F(GL_MAP1_GRID_DOMAIN, 0, 1), F(GL_MAP2_GRID_DOMAIN, 0, 1, 0, 1),
      I(GL_MAP1_GRID_SEGMENTS, 1), I(GL_MAP2_GRID_SEGMENTS, 1, 1), OFF(GL_AUTO_NORMAL),
      // 6.26 Hints
      I(GL_PERSPECTIVE_CORRECTION_HINT, GL_DONT_CARE), I(GL_POINT_SMOOTH_HINT, GL_DONT_CARE),
      I(GL_LINE_SMOOTH_HINT, GL_DONT_CARE), I(GL_POLYGON_SMOOTH_HINT, GL_DONT_CARE), I(GL_FOG_HINT, GL_DONT_CARE),
      I(GL_GENERATE_MIPMAP_HINT, GL_DONT_CARE), I(GL_TEXTURE_COMPRESSION_HINT, GL_DONT_CARE),
      // 6.27-6.29 Implementation-dependent values: Pineda's
      I(GL_MAX_LIGHTS, 8), I(GL_MAX_CLIP_PLANES, 6), I(GL_MAX_MODELVIEW_STACK_DEPTH, 32),
      I(GL_MAX_PROJECTION_STACK_DEPTH, 10), I(GL_MAX_TEXTURE_STACK_DEPTH, 10), I(GL_SUBPIXEL_BITS, 8),
      I(GL_MAX_3D_TEXTURE_SIZE, 256), I(GL_MAX_TEXTURE_SIZE, 8192), I(GL_MAX_CUBE_MAP_TEXTURE_SIZE, 4096),
      I(GL_MAX_RECTANGLE_TEXTURE_SIZE_ARB, 8192),
      I(GL_MAX_PIXEL_MAP_TABLE, 256), I(GL_MAX_NAME_STACK_DEPTH, 64), I(GL_MAX_LIST_NESTING, 64),
      I(GL_MAX_EVAL_ORDER, 30), I(GL_MAX_VIEWPORT_DIMS, 16384, 16384), I(GL_MAX_ATTRIB_STACK_DEPTH, 16),
      I(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, 16), I(GL_MAX_ELEMENTS_INDICES, 3000), I(GL_MAX_ELEMENTS_VERTICES, 3000),
      I(GL_MAX_TEXTURE_UNITS, 4), F(GL_MAX_TEXTURE_LOD_BIAS, 16),
      // Aliased sizes are whole pixels; smooth ones are exact to 1/256 pixel (as coordinates are).
      F(GL_ALIASED_POINT_SIZE_RANGE, 1, 255), F(GL_SMOOTH_POINT_SIZE_RANGE, 1, 255),
      F(GL_SMOOTH_POINT_SIZE_GRANULARITY, 1.0 / 256), F(GL_POINT_SIZE_RANGE, 1, 255),
      F(GL_POINT_SIZE_GRANULARITY, 1.0 / 256), F(GL_ALIASED_LINE_WIDTH_RANGE, 1, 255),
      F(GL_SMOOTH_LINE_WIDTH_RANGE, 1, 255), F(GL_SMOOTH_LINE_WIDTH_GRANULARITY, 1.0 / 256),
      F(GL_LINE_WIDTH_RANGE, 1, 255), F(GL_LINE_WIDTH_GRANULARITY, 1.0 / 256),
      I(GL_SAMPLE_BUFFERS, 0), I(GL_SAMPLES, 0), I(GL_NUM_COMPRESSED_TEXTURE_FORMATS, 0),
      ROW(Query, GL_SAMPLES_PASSED, GL_QUERY_COUNTER_BITS, 0, 64),
      // 6.30 Implementation-dependent pixel depths: the test's single-buffered RGBA8, 24-bit depth, 8-bit stencil surface
      I(GL_RED_BITS, 8), I(GL_GREEN_BITS, 8), I(GL_BLUE_BITS, 8), I(GL_ALPHA_BITS, 8), I(GL_INDEX_BITS, 0),
      I(GL_DEPTH_BITS, 24), I(GL_STENCIL_BITS, 8), I(GL_ACCUM_RED_BITS, 16), I(GL_ACCUM_GREEN_BITS, 16),
      I(GL_ACCUM_BLUE_BITS, 16), I(GL_ACCUM_ALPHA_BITS, 16), B(GL_RGBA_MODE, 1), B(GL_INDEX_MODE, 0),
      B(GL_DOUBLEBUFFER, 0), B(GL_STEREO, 0), I(GL_AUX_BUFFERS, 0),
      // 6.31 Miscellaneous
      I(GL_LIST_BASE, 0), I(GL_LIST_INDEX, 0), I(GL_LIST_MODE, 0), I(GL_ATTRIB_STACK_DEPTH, 0),
      I(GL_CLIENT_ATTRIB_STACK_DEPTH, 0), I(GL_NAME_STACK_DEPTH, 0), I(GL_RENDER_MODE, GL_RENDER),
      ROW(Pointer, 0, GL_SELECTION_BUFFER_POINTER, 0, 0), I(GL_SELECTION_BUFFER_SIZE, 0),
      ROW(Pointer, 0, GL_FEEDBACK_BUFFER_POINTER, 0, 0), I(GL_FEEDBACK_BUFFER_SIZE, 0),
      I(GL_FEEDBACK_BUFFER_TYPE, GL_2D), ROW(Query, GL_SAMPLES_PASSED, GL_CURRENT_QUERY, 0, 0),
      ROW(Stipple, 0, 0, 0),
  };
  rows.back().expected.assign(128, 255);  // the polygon stipple starts all ones

  // 6.10/6.11 Materials (both faces) and lights
  for (GLenum face : {GL_FRONT, GL_BACK}) {
    rows.push_back(ROW(Material, face, GL_AMBIENT, 0, 0.2f, 0.2f, 0.2f, 1));
    rows.push_back(ROW(Material, face, GL_DIFFUSE, 0, 0.8f, 0.8f, 0.8f, 1));
    rows.push_back(ROW(Material, face, GL_SPECULAR, 0, 0, 0, 0, 1));
    rows.push_back(ROW(Material, face, GL_EMISSION, 0, 0, 0, 0, 1));
    rows.push_back(ROW(Material, face, GL_SHININESS, 0, 0));
    rows.push_back(ROW(Material, face, GL_COLOR_INDEXES, 0, 0, 1, 1));
  }
  for (int light = 0; light < 8; ++light) {
    const double on = light == 0 ? 1 : 0;
    rows.push_back(ROW(Light, 0, GL_AMBIENT, light, 0, 0, 0, 1));
    rows.push_back(ROW(Light, 0, GL_DIFFUSE, light, on, on, on, 1));
    rows.push_back(ROW(Light, 0, GL_SPECULAR, light, on, on, on, 1));
    rows.push_back(ROW(Light, 0, GL_POSITION, light, 0, 0, 1, 0));
    rows.push_back(ROW(Light, 0, GL_CONSTANT_ATTENUATION, light, 1));
    rows.push_back(ROW(Light, 0, GL_LINEAR_ATTENUATION, light, 0));
    rows.push_back(ROW(Light, 0, GL_QUADRATIC_ATTENUATION, light, 0));
    rows.push_back(ROW(Light, 0, GL_SPOT_DIRECTION, light, 0, 0, -1));
    rows.push_back(ROW(Light, 0, GL_SPOT_EXPONENT, light, 0));
    rows.push_back(ROW(Light, 0, GL_SPOT_CUTOFF, light, 180));
    rows.push_back(Row{Get::Enabled, 0, GLenum(GL_LIGHT0 + light), 0, {0}, 0, "GL_LIGHTi"});
  }
  // 6.8 Clip planes
  for (int plane = 0; plane < 6; ++plane) {
    rows.push_back(ROW(ClipPlane, 0, 0, plane, 0, 0, 0, 0));
    rows.push_back(Row{Get::Enabled, 0, GLenum(GL_CLIP_PLANE0 + plane), 0, {0}, 0, "GL_CLIP_PLANEi"});
  }

  // Per texture unit: 6.5, 6.6, 6.8 (texture matrix), 6.14 and 6.17.
  for (int unit = 0; unit < 4; ++unit) {
    std::vector<Row> per_unit = {
        F(GL_CURRENT_TEXTURE_COORDS, 0, 0, 0, 1),
        F(GL_CURRENT_RASTER_TEXTURE_COORDS, 0, 0, 0, 1),
        OFF(GL_TEXTURE_COORD_ARRAY),
        I(GL_TEXTURE_COORD_ARRAY_SIZE, 4),
        F(GL_TEXTURE_MATRIX, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1),
        I(GL_TEXTURE_STACK_DEPTH, 1),
        OFF(GL_TEXTURE_1D), OFF(GL_TEXTURE_2D), OFF(GL_TEXTURE_3D), OFF(GL_TEXTURE_CUBE_MAP),
        OFF(GL_TEXTURE_RECTANGLE_ARB),
        I(GL_TEXTURE_BINDING_1D, 0), I(GL_TEXTURE_BINDING_2D, 0), I(GL_TEXTURE_BINDING_3D, 0),
        I(GL_TEXTURE_BINDING_CUBE_MAP, 0), I(GL_TEXTURE_BINDING_RECTANGLE_ARB, 0),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, 0, GL_MODULATE),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, 0, 0, 0, 0, 0),
        ROW(TexEnv, GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0, 0),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_COMBINE_RGB, 0, GL_MODULATE),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_COMBINE_ALPHA, 0, GL_MODULATE),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_SRC0_RGB, 0, GL_TEXTURE),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_SRC1_RGB, 0, GL_PREVIOUS),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_SRC2_RGB, 0, GL_CONSTANT),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_SRC0_ALPHA, 0, GL_TEXTURE),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_SRC1_ALPHA, 0, GL_PREVIOUS),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_SRC2_ALPHA, 0, GL_CONSTANT),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_OPERAND0_RGB, 0, GL_SRC_COLOR),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_OPERAND1_RGB, 0, GL_SRC_COLOR),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_OPERAND2_RGB, 0, GL_SRC_ALPHA),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, 0, GL_SRC_ALPHA),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_OPERAND1_ALPHA, 0, GL_SRC_ALPHA),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_OPERAND2_ALPHA, 0, GL_SRC_ALPHA),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_RGB_SCALE, 0, 1),
        ROW(TexEnv, GL_TEXTURE_ENV, GL_ALPHA_SCALE, 0, 1),
        OFF(GL_TEXTURE_GEN_S), OFF(GL_TEXTURE_GEN_T), OFF(GL_TEXTURE_GEN_R), OFF(GL_TEXTURE_GEN_Q),
        ROW(TexGen, GL_S, GL_OBJECT_PLANE, 0, 1, 0, 0, 0),
        ROW(TexGen, GL_T, GL_OBJECT_PLANE, 0, 0, 1, 0, 0),
        ROW(TexGen, GL_R, GL_OBJECT_PLANE, 0, 0, 0, 0, 0),
        ROW(TexGen, GL_Q, GL_OBJECT_PLANE, 0, 0, 0, 0, 0),
        ROW(TexGen, GL_S, GL_EYE_PLANE, 0, 1, 0, 0, 0),
        ROW(TexGen, GL_T, GL_EYE_PLANE, 0, 0, 1, 0, 0),
        ROW(TexGen, GL_R, GL_EYE_PLANE, 0, 0, 0, 0, 0),
        ROW(TexGen, GL_Q, GL_EYE_PLANE, 0, 0, 0, 0, 0),
        ROW(TexGen, GL_S, GL_TEXTURE_GEN_MODE, 0, GL_EYE_LINEAR),
        ROW(TexGen, GL_T, GL_TEXTURE_GEN_MODE, 0, GL_EYE_LINEAR),
        ROW(TexGen, GL_R, GL_TEXTURE_GEN_MODE, 0, GL_EYE_LINEAR),
        ROW(TexGen, GL_Q, GL_TEXTURE_GEN_MODE, 0, GL_EYE_LINEAR),
    };
    for (Row& r : per_unit) {
      r.unit = unit;
      rows.push_back(r);
    }
  }
  return rows;
}

#undef ROW
#undef F
#undef I
#undef B
#undef OFF
#undef ON

constexpr float kUnwritten = -7777.f;

// The values a row's query returns, as many as it writes (at most 128).
std::vector<double> query(const Row& r) {
  glActiveTexture(GL_TEXTURE0 + r.unit);
  glClientActiveTexture(GL_TEXTURE0 + r.unit);
  std::vector<float> f(129, kUnwritten);
  std::vector<GLint> i(129, static_cast<GLint>(kUnwritten));
  std::vector<GLboolean> b(129, 77);
  auto floats = [&] {
    std::vector<double> out;
    for (float v : f) {
      if (v == kUnwritten) break;
      out.push_back(v);
    }
    return out;
  };
  auto ints = [&] {
    std::vector<double> out;
    for (GLint v : i) {
      if (v == static_cast<GLint>(kUnwritten)) break;
      out.push_back(v);
    }
    return out;
  };
  switch (r.get) {
    case Get::Float: glGetFloatv(r.pname, f.data()); return floats();
    case Get::Integer: glGetIntegerv(r.pname, i.data()); return ints();
    case Get::Boolean: {
      glGetBooleanv(r.pname, b.data());
      std::vector<double> out;
      for (GLboolean v : b) {
        if (v == 77) break;
        out.push_back(v);
      }
      return out;
    }
    case Get::Enabled: return {double(glIsEnabled(r.pname))};
    case Get::Light: glGetLightfv(GL_LIGHT0 + r.index, r.pname, f.data()); return floats();
    case Get::Material: glGetMaterialfv(r.target, r.pname, f.data()); return floats();
    case Get::TexEnv: glGetTexEnvfv(r.target, r.pname, f.data()); return floats();
    case Get::TexGen: glGetTexGenfv(r.target, r.pname, f.data()); return floats();
    case Get::TexParam: glGetTexParameterfv(r.target, r.pname, f.data()); return floats();
    case Get::TexLevel: glGetTexLevelParameterfv(r.target, r.index, r.pname, f.data()); return floats();
    case Get::Map: glGetMapfv(r.target, r.pname, f.data()); return floats();
    case Get::Query: glGetQueryiv(r.target, r.pname, i.data()); return ints();
    case Get::ClipPlane: {
      GLdouble eq[5] = {-7777, -7777, -7777, -7777, -7777};
      glGetClipPlane(GL_CLIP_PLANE0 + r.index, eq);
      return {eq[0], eq[1], eq[2], eq[3]};
    }
    case Get::Pointer: {
      void* p = &p;
      glGetPointerv(r.pname, &p);
      return {double(reinterpret_cast<uintptr_t>(p))};
    }
    case Get::Buffer: {
      GLuint buffer = 0;
      glGenBuffers(1, &buffer);
      glBindBuffer(r.target, buffer);
      glGetBufferParameteriv(r.target, r.pname, i.data());
      glBindBuffer(r.target, 0);
      glDeleteBuffers(1, &buffer);
      return ints();
    }
    case Get::Stipple: {
      GLubyte pattern[128];
      std::fill(std::begin(pattern), std::end(pattern), 0);
      glGetPolygonStipple(pattern);
      return std::vector<double>(std::begin(pattern), std::end(pattern));
    }
  }
  return {};
}

// Floats compare at float precision (0.2f reads back as 0.2f, not 0.2).
bool same(const std::vector<double>& got, const std::vector<double>& expected) {
  if (got.size() != expected.size()) return false;
  for (size_t k = 0; k < got.size(); ++k)
    if (static_cast<float>(got[k]) != static_cast<float>(expected[k])) return false;
  return true;
}

std::string describe(const std::vector<double>& v) {
  std::string s = "(";
  for (size_t k = 0; k < v.size(); ++k) s += (k ? ", " : "") + std::to_string(v[k]);
  return s + ")";
}

class InitialStateTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {40, 24, 24, 8}; }
};

TEST_F(InitialStateTest, EveryValueOfTheStateTables) {
  GLboolean double_buffered = GL_TRUE;
  glGetBooleanv(GL_DOUBLEBUFFER, &double_buffered);
  ASSERT_EQ(double_buffered, GL_FALSE) << "the rows expect the test surface's single buffer (GL_FRONT)";
  int checked = 0;
  for (const Row& r : initial_state_rows()) {
    const std::vector<double> got = query(r);
    EXPECT_TRUE(same(got, r.expected)) << r.name << " (target 0x" << std::hex << r.target << std::dec << ", index "
                                       << r.index << ", unit " << r.unit << "): got " << describe(got)
                                       << ", expected " << describe(r.expected);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << r.name;
    ++checked;
  }
  EXPECT_EQ(checked, 664);
}

}  // namespace
}  // namespace pineda::test
