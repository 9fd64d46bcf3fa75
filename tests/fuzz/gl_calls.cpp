#define GL_GLEXT_PROTOTYPES
#include "tests/fuzz/gl_calls.h"

#include <GL/glext.h>

#include <algorithm>
#include <vector>

#include "tests/fuzz/client_arrays.h"
#include "tests/fuzz/es_prototypes.h"
#include "tests/fuzz/object_names.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kCapabilities[] = {
    GL_BLEND, GL_DEPTH_TEST, GL_LIGHTING, GL_LIGHT0, GL_LIGHT7, GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D,
    GL_TEXTURE_CUBE_MAP, GL_CULL_FACE, GL_FOG, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_SCISSOR_TEST, GL_POLYGON_STIPPLE,
    GL_LINE_STIPPLE, GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE, GL_NORMALIZE, GL_RESCALE_NORMAL,
    GL_COLOR_MATERIAL, GL_CLIP_PLANE0, GL_CLIP_PLANE5, GL_TEXTURE_GEN_S, GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R,
    GL_TEXTURE_GEN_Q, GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP1_COLOR_4, GL_MAP1_TEXTURE_COORD_2,
    GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_MAP2_NORMAL, GL_MAP2_TEXTURE_COORD_2, GL_AUTO_NORMAL, GL_COLOR_LOGIC_OP,
    GL_DITHER, GL_POINT_SMOOTH, GL_LINE_SMOOTH, GL_POLYGON_SMOOTH, GL_COLOR_SUM, GL_MULTISAMPLE,
    GL_SAMPLE_ALPHA_TO_COVERAGE, GL_INDEX_LOGIC_OP, GL_POINT_SPRITE};
constexpr GLenum kClientArrays[] = {GL_VERTEX_ARRAY, GL_COLOR_ARRAY, GL_NORMAL_ARRAY, GL_TEXTURE_COORD_ARRAY,
                                    GL_INDEX_ARRAY, GL_EDGE_FLAG_ARRAY, GL_FOG_COORD_ARRAY,
                                    GL_SECONDARY_COLOR_ARRAY};
constexpr GLenum kPrimitives[] = {GL_POINTS,         GL_LINES,     GL_LINE_LOOP,  GL_LINE_STRIP, GL_TRIANGLES,
                                  GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS, GL_QUAD_STRIP, GL_POLYGON};
constexpr GLenum kCompare[] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL, GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
constexpr GLenum kBlendFactors[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_SRC_COLOR, GL_DST_COLOR,
                                    GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA,
                                    GL_SRC_ALPHA_SATURATE, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA};
constexpr GLenum kStencilOps[] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR, GL_DECR, GL_INVERT, GL_INCR_WRAP,
                                  GL_DECR_WRAP};
constexpr GLenum kFaces[] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
constexpr GLenum kBindTargets[] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP,
                                   GL_TEXTURE_RECTANGLE_ARB};
constexpr GLenum kImage1DTargets[] = {GL_TEXTURE_1D, GL_PROXY_TEXTURE_1D};
constexpr GLenum kImage2DTargets[] = {GL_TEXTURE_2D,
                                      GL_PROXY_TEXTURE_2D,
                                      GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                                      GL_TEXTURE_CUBE_MAP_NEGATIVE_Y,
                                      GL_TEXTURE_CUBE_MAP_POSITIVE_Z,
                                      GL_PROXY_TEXTURE_CUBE_MAP};
constexpr GLenum kImage3DTargets[] = {GL_TEXTURE_3D, GL_PROXY_TEXTURE_3D};
constexpr GLenum kInternalFormats[] = {1,           2,          3,
                                       4,           GL_RGBA,    GL_RGB,
                                       GL_ALPHA,    GL_LUMINANCE, GL_LUMINANCE_ALPHA,
                                       GL_INTENSITY, GL_RGBA8,  GL_RGB5_A1,
                                       GL_LUMINANCE16, GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT24,
                                       GL_R3_G3_B2, GL_COMPRESSED_RGBA, GL_RGB10_A2,
                                       GL_ALPHA12,  GL_INTENSITY4};
constexpr GLenum kFormats[] = {GL_COLOR_INDEX, GL_STENCIL_INDEX, GL_DEPTH_COMPONENT, GL_RED, GL_GREEN, GL_BLUE,
                               GL_ALPHA, GL_RGB, GL_RGBA, GL_BGR, GL_BGRA, GL_LUMINANCE, GL_LUMINANCE_ALPHA};
constexpr GLenum kTypes[] = {GL_UNSIGNED_BYTE,
                             GL_BYTE,
                             GL_BITMAP,
                             GL_UNSIGNED_SHORT,
                             GL_SHORT,
                             GL_UNSIGNED_INT,
                             GL_INT,
                             GL_FLOAT,
                             GL_UNSIGNED_BYTE_3_3_2,
                             GL_UNSIGNED_BYTE_2_3_3_REV,
                             GL_UNSIGNED_SHORT_5_6_5,
                             GL_UNSIGNED_SHORT_4_4_4_4_REV,
                             GL_UNSIGNED_SHORT_5_5_5_1,
                             GL_UNSIGNED_SHORT_1_5_5_5_REV,
                             GL_UNSIGNED_INT_8_8_8_8,
                             GL_UNSIGNED_INT_8_8_8_8_REV,
                             GL_UNSIGNED_INT_10_10_10_2,
                             GL_UNSIGNED_INT_2_10_10_10_REV};
constexpr GLenum kArrayTypes[] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT,
                                  GL_INT,  GL_UNSIGNED_INT,  GL_FLOAT, GL_DOUBLE};
constexpr GLenum kIndexTypes[] = {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT};
constexpr GLenum kPixelStoreNames[] = {
    GL_UNPACK_ALIGNMENT,    GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS,  GL_UNPACK_SKIP_PIXELS,
    GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES, GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST,
    GL_PACK_ALIGNMENT,      GL_PACK_ROW_LENGTH,   GL_PACK_SKIP_ROWS,    GL_PACK_SKIP_PIXELS,
    GL_PACK_IMAGE_HEIGHT,   GL_PACK_SKIP_IMAGES,  GL_PACK_SWAP_BYTES,   GL_PACK_LSB_FIRST};
constexpr GLenum kPixelMaps[] = {GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_I_TO_A,
                                 GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G, GL_PIXEL_MAP_A_TO_A};
constexpr GLenum kTransferNames[] = {GL_MAP_COLOR,  GL_MAP_STENCIL, GL_INDEX_SHIFT, GL_INDEX_OFFSET, GL_RED_SCALE,
                                     GL_GREEN_BIAS, GL_ALPHA_SCALE, GL_DEPTH_SCALE, GL_DEPTH_BIAS};
constexpr GLenum kTexParamNames[] = {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER,  GL_TEXTURE_WRAP_S,
                                     GL_TEXTURE_WRAP_T,     GL_TEXTURE_WRAP_R,      GL_TEXTURE_MIN_LOD,
                                     GL_TEXTURE_MAX_LOD,    GL_TEXTURE_BASE_LEVEL,  GL_TEXTURE_MAX_LEVEL,
                                     GL_TEXTURE_LOD_BIAS,   GL_GENERATE_MIPMAP,     GL_TEXTURE_PRIORITY,
                                     GL_DEPTH_TEXTURE_MODE, GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC,
                                     GL_TEXTURE_BORDER_COLOR, GL_TEXTURE_SRGB_DECODE_EXT, GL_TEXTURE_SWIZZLE_R,
                                     GL_TEXTURE_SWIZZLE_A,  GL_TEXTURE_SWIZZLE_RGBA};
constexpr GLenum kTexParamValues[] = {GL_NEAREST, GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
                                      GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER,
                                      GL_MIRRORED_REPEAT, GL_TRUE, GL_FALSE, GL_LUMINANCE, GL_INTENSITY,
                                      GL_COMPARE_R_TO_TEXTURE, GL_LEQUAL, GL_NONE, GL_SKIP_DECODE_EXT, GL_RED,
                                      GL_ALPHA, GL_ONE};
constexpr GLenum kTexEnvNames[] = {GL_TEXTURE_ENV_MODE, GL_COMBINE_RGB,  GL_COMBINE_ALPHA, GL_SOURCE0_RGB,
                                   GL_SOURCE1_ALPHA,    GL_OPERAND0_RGB, GL_OPERAND2_ALPHA, GL_RGB_SCALE,
                                   GL_ALPHA_SCALE,      GL_TEXTURE_ENV_COLOR, GL_TEXTURE_LOD_BIAS};
constexpr GLenum kTexEnvValues[] = {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD, GL_COMBINE,
                                    GL_INTERPOLATE, GL_DOT3_RGBA, GL_SUBTRACT, GL_TEXTURE, GL_PRIMARY_COLOR,
                                    GL_PREVIOUS, GL_CONSTANT, GL_SRC_COLOR, GL_ONE_MINUS_SRC_ALPHA, GL_TEXTURE1};
constexpr GLenum kLightNames[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION,
                                  GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
                                  GL_QUADRATIC_ATTENUATION};
constexpr GLenum kMaterialNames[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS,
                                     GL_AMBIENT_AND_DIFFUSE, GL_COLOR_INDEXES};
constexpr GLenum kFogNames[] = {GL_FOG_MODE, GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_COLOR,
                                GL_FOG_COORD_SRC};
constexpr GLenum kFogValues[] = {GL_LINEAR, GL_EXP, GL_EXP2, GL_FOG_COORD, GL_FRAGMENT_DEPTH};
constexpr GLenum kTexGenNames[] = {GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE};
constexpr GLenum kTexGenModes[] = {GL_OBJECT_LINEAR, GL_EYE_LINEAR, GL_SPHERE_MAP, GL_NORMAL_MAP, GL_REFLECTION_MAP};
constexpr GLenum kCoords[] = {GL_S, GL_T, GL_R, GL_Q};
constexpr GLenum kMap1Targets[] = {GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP1_COLOR_4, GL_MAP1_NORMAL,
                                   GL_MAP1_TEXTURE_COORD_1, GL_MAP1_TEXTURE_COORD_4, GL_MAP1_INDEX};
constexpr GLenum kMap2Targets[] = {GL_MAP2_VERTEX_3, GL_MAP2_VERTEX_4, GL_MAP2_COLOR_4, GL_MAP2_NORMAL,
                                   GL_MAP2_TEXTURE_COORD_2, GL_MAP2_TEXTURE_COORD_3, GL_MAP2_INDEX};
constexpr GLenum kMatrixModes[] = {GL_MODELVIEW, GL_PROJECTION, GL_TEXTURE};
constexpr GLenum kGetNames[] = {
    GL_CURRENT_COLOR,     GL_CURRENT_RASTER_POSITION, GL_MODELVIEW_MATRIX, GL_PROJECTION_MATRIX,
    GL_TEXTURE_MATRIX,    GL_VIEWPORT,                GL_MAX_TEXTURE_SIZE, GL_LIST_INDEX,
    GL_LIST_MODE,         GL_TEXTURE_BINDING_2D,      GL_PIXEL_MAP_I_TO_R_SIZE, GL_UNPACK_SKIP_IMAGES,
    GL_COMPRESSED_TEXTURE_FORMATS, GL_FOG_COLOR,      GL_LIGHT_MODEL_AMBIENT, GL_POLYGON_MODE,
    GL_ARRAY_BUFFER_BINDING, GL_VERTEX_ARRAY_POINTER, GL_FEEDBACK_BUFFER_SIZE, GL_MAP2_GRID_DOMAIN,
    GL_ACCUM_CLEAR_VALUE, GL_DEPTH_RANGE,             GL_SCISSOR_BOX,      GL_COLOR_WRITEMASK,
    GL_VERTEX_ARRAY_BINDING};
// No element array buffer: see glBindBuffer. Pixel calls take offsets into pixel buffers (image_source).
constexpr GLenum kBufferTargets[] = {GL_ARRAY_BUFFER, GL_PIXEL_PACK_BUFFER, GL_PIXEL_UNPACK_BUFFER,
                                     GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER};
constexpr GLenum kBufferUsages[] = {GL_STATIC_DRAW, GL_DYNAMIC_DRAW, GL_STREAM_READ};

// Vertex indices of a draw, all within what the client arrays hold.
std::vector<uint8_t> index_bytes(FuzzInput& in, GLenum type, GLsizei count) {
  std::vector<uint8_t> bytes(size_t(std::max(count, 0)) * 4 + 4);
  for (GLsizei i = 0; i < count; ++i) {
    const GLuint index = GLuint(in.integer(0, kMaxVertexIndex)) % (kMaxVertexIndex + 1);
    if (type == GL_UNSIGNED_BYTE) bytes[i] = uint8_t(index);
    else if (type == GL_UNSIGNED_SHORT) reinterpret_cast<GLushort*>(bytes.data())[i] = GLushort(index);
    else reinterpret_cast<GLuint*>(bytes.data())[i] = index;
  }
  return bytes;
}

// glCallList(s) may be compiled into a list only once: a list calling lists twice can
// call 2^64 lists through 64 levels of nesting, a legitimate hang. Between glBegin and
// glEnd (GL_COMPILE_AND_EXECUTE) the query fails and leaves -1: a list may be compiling.
bool compiling_list() {
  GLint compiling = -1;
  glGetIntegerv(GL_LIST_INDEX, &compiling);
  return compiling != 0;
}

bool may_call_lists(ClientMemory& memory) {
  if (!compiling_list()) return true;
  return memory.calls_to_lists_in_list++ == 0;
}

// The last grid step of a mesh from `first`: extremes stay (an empty range, or steps near
// INT_MIN/INT_MAX), but at most 64 steps a side. A million-vertex mesh is an application's
// request that takes seconds, not a bug.
GLint mesh_end(GLint first, GLint last) { return GLint(std::min<int64_t>(last, int64_t(first) + 64)); }

void tex_image_2d(FuzzInput& in, ClientMemory& memory) {
  const GLenum target = in.enumeration(kImage2DTargets);
  const GLint level = in.integer(0, 4);
  const GLint internal_format = GLint(in.enumeration(kInternalFormats));
  const CheckedSize w = in.checked_size(17), h = in.checked_size(17);
  const GLint border = in.integer(0, 1);
  const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
  const void* pixels = in.boolean() ? nullptr : memory.image_source(image_footprint(false, w.value, h.value, 1), w.huge || h.huge);
  glTexImage2D(target, level, internal_format, w.value, h.value, border, format, type, pixels);
}

void tex_image_3d(FuzzInput& in, ClientMemory& memory) {
  const GLenum target = in.enumeration(kImage3DTargets);
  const GLint level = in.integer(0, 3);
  const GLint internal_format = GLint(in.enumeration(kInternalFormats));
  const CheckedSize w = in.checked_size(9), h = in.checked_size(9), d = in.checked_size(9);
  const GLint border = in.integer(0, 1);
  const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
  const bool huge = w.huge || h.huge || d.huge;
  const void* pixels = in.boolean() ? nullptr : memory.image_source(image_footprint(false, w.value, h.value, d.value), huge);
  glTexImage3D(target, level, internal_format, w.value, h.value, d.value, border, format, type, pixels);
}

// The calls that have other names (ARB, EXT, ATI) take the call as a template argument.
template <auto Call>
void active_texture(FuzzInput& in, ClientMemory& memory) {
  Call(in.enumeration({GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE3, GL_TEXTURE4}));
}

template <auto Call>
void client_active_texture(FuzzInput& in, ClientMemory& memory) {
  Call(in.enumeration({GL_TEXTURE0, GL_TEXTURE2, GL_TEXTURE5}));
}

template <auto Call>
void array_element(FuzzInput& in, ClientMemory& memory) {
  Call(std::min(in.integer(-1, kMaxVertexIndex), kMaxVertexIndex));
}

template <auto Call>
void draw_arrays(FuzzInput& in, ClientMemory& memory) {
  const GLenum mode = in.enumeration(kPrimitives);
  const GLint first = std::min(in.integer(-1, 64), 64);
  const GLsizei count = std::min(in.bounded_size(64), kMaxVertexIndex - 64);
  Call(mode, first, count);
}

template <auto Call>
void draw_range_elements(FuzzInput& in, ClientMemory& memory) {
  const GLenum mode = in.enumeration(kPrimitives), type = in.enumeration(kIndexTypes);
  const GLuint start = GLuint(in.integer(0, 100)), end = GLuint(in.integer(0, 1000));
  const GLsizei count = in.bounded_size(64);
  const std::vector<uint8_t> indices = index_bytes(in, type, count);
  Call(mode, start, end, count, type, indices.data());
}

template <auto Call>
void multi_draw_arrays(FuzzInput& in, ClientMemory& memory) {
  const GLint first[3] = {in.integer(0, 64) & 63, in.integer(0, 64) & 63, in.integer(0, 64) & 63};
  const GLsizei count[3] = {in.bounded_size(64), in.bounded_size(64), in.bounded_size(64)};
  Call(in.enumeration(kPrimitives), first, count, std::min(in.bounded_size(3), 3));
}

template <auto Call>
void blend_equation(FuzzInput& in, ClientMemory& memory) {
  Call(in.enumeration({GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX}));
}

template <auto Call>
void stencil_op_separate(FuzzInput& in, ClientMemory& memory) {
  Call(in.enumeration(kFaces), in.enumeration(kStencilOps), in.enumeration(kStencilOps), in.enumeration(kStencilOps));
}


template <auto Call>
void begin_query(FuzzInput& in, ClientMemory& memory) {
  Call(in.enumeration({GL_SAMPLES_PASSED}), in.name());
}

template <auto Call>
void end_query(FuzzInput& in, ClientMemory& memory) {
  Call(in.enumeration({GL_SAMPLES_PASSED}));
}

template <auto Call>
void get_query_objectuiv(FuzzInput& in, ClientMemory& memory) {
  GLuint v = 0;
  Call(in.name(), in.enumeration({GL_QUERY_RESULT, GL_QUERY_RESULT_AVAILABLE}), &v);
}


// Never GL_ELEMENT_ARRAY_BUFFER: its indices would come from buffer data, and client arrays
// read at any index past what the application holds.
template <auto Call>
void bind_buffer(FuzzInput& in, ClientMemory& memory) {
  memory.pixel_buffer_offset = uintptr_t(in.integer(0, 4096));
  Call(in.enumeration(kBufferTargets), in.name());
}

template <auto Call>
void buffer_data(FuzzInput& in, ClientMemory& memory) {
  const GLsizeiptr size = in.bounded_size(4096);
  Call(in.enumeration(kBufferTargets), size, in.boolean() ? memory.arrays.data() : nullptr,
               in.enumeration(kBufferUsages));
}

template <auto Call>
void buffer_sub_data(FuzzInput& in, ClientMemory& memory) {
  Call(in.enumeration(kBufferTargets), in.integer(-1, 4096), in.bounded_size(4096), memory.arrays.data());
}

template <auto Call>
void get_buffer_sub_data(FuzzInput& in, ClientMemory& memory) {
  std::vector<uint8_t> out(4096);
  Call(in.enumeration(kBufferTargets), in.integer(-1, 4096), in.bounded_size(4096), out.data());
}

template <auto Call>
void map_buffer(FuzzInput& in, ClientMemory& memory) {
  const GLenum target = in.enumeration(kBufferTargets);
  void* p = Call(target, in.enumeration({GL_READ_ONLY, GL_WRITE_ONLY, GL_READ_WRITE}));
  GLint size = 0;
  glGetBufferParameteriv(target, GL_BUFFER_SIZE, &size);
  if (p && size > 0) static_cast<uint8_t*>(p)[size - 1] ^= 1;
}

// A range inside or around the buffer, with any mix of the access bits and a stray one; what
// comes back is written at its last byte (the mapped length is what GL says it is).
void map_buffer_range(FuzzInput& in, ClientMemory&) {
  const GLenum target = in.enumeration(kBufferTargets);
  const GLbitfield access = static_cast<GLbitfield>(in.integer(0, 0x7f)) | (in.integer(0, 7) == 0 ? 0x100u : 0u);
  void* p = glMapBufferRange(target, in.integer(-4, 64), in.integer(-4, 80), access);
  GLint length = 0;
  glGetBufferParameteriv(target, GL_BUFFER_MAP_LENGTH, &length);
  if (p && length > 0 && (access & GL_MAP_WRITE_BIT)) static_cast<uint8_t*>(p)[length - 1] ^= 1;
}

template <auto Call>
void unmap_buffer(FuzzInput& in, ClientMemory& memory) {
  Call(in.enumeration(kBufferTargets));
}

template <auto Call>
void delete_buffers(FuzzInput& in, ClientMemory& memory) {
  GLuint names[2] = {in.name(), in.name()};
  for (GLuint& name : names)
    if (name != 0 && array_uses_buffer(name)) name = 0;  // 0 is skipped
  Call(in.bounded_size(2), names);
}

const GlCall kCalls[] = {
    {"glEnable", [](FuzzInput& in, ClientMemory&) { glEnable(in.enumeration(kCapabilities)); }},
    {"glDisable", [](FuzzInput& in, ClientMemory&) { glDisable(in.enumeration(kCapabilities)); }},
    {"glBegin", [](FuzzInput& in, ClientMemory&) { glBegin(in.enumeration(kPrimitives)); }},
    {"glEnd", [](FuzzInput&, ClientMemory&) { glEnd(); }},
    {"glVertex3f", [](FuzzInput& in, ClientMemory&) { glVertex3f(in.real() * 8, in.real() * 8, in.real()); }},
    {"glVertex4f", [](FuzzInput& in, ClientMemory&) { glVertex4f(in.real(), in.real(), in.real(), in.real()); }},
    {"glColor4f", [](FuzzInput& in, ClientMemory&) { glColor4f(in.unit(), in.unit(), in.unit(), in.unit()); }},
    {"glNormal3f", [](FuzzInput& in, ClientMemory&) { glNormal3f(in.real(), in.real(), in.real()); }},
    {"glTexCoord4f", [](FuzzInput& in, ClientMemory&) { glTexCoord4f(in.real(), in.real(), in.real(), in.real()); }},
    {"glMultiTexCoord2f",
     [](FuzzInput& in, ClientMemory&) {
       glMultiTexCoord2f(in.enumeration({GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE3, GL_TEXTURE4}), in.real(), in.real());
     }},
    {"glEdgeFlag", [](FuzzInput& in, ClientMemory&) { glEdgeFlag(in.boolean()); }},
    {"glIndexf", [](FuzzInput& in, ClientMemory&) { glIndexf(in.real()); }},
    {"glFogCoordf", [](FuzzInput& in, ClientMemory&) { glFogCoordf(in.real()); }},
    {"glSecondaryColor3f",
     [](FuzzInput& in, ClientMemory&) { glSecondaryColor3f(in.unit(), in.unit(), in.unit()); }},
    {"glRectf", [](FuzzInput& in, ClientMemory&) { glRectf(in.real() * 8, in.real() * 8, in.real() * 8, in.real() * 8); }},
    {"glClear",
     [](FuzzInput& in, ClientMemory&) {
       glClear(in.boolean() ? GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT | GL_ACCUM_BUFFER_BIT
                            : GLbitfield(in.integer(0, 0xffff)));
     }},
    {"glClearColor", [](FuzzInput& in, ClientMemory&) { glClearColor(in.unit(), in.unit(), in.unit(), in.unit()); }},
    {"glViewport",
     [](FuzzInput& in, ClientMemory&) { glViewport(in.integer(-8, 32), in.integer(-8, 32), in.integer(0, 64), in.integer(0, 64)); }},
    {"glScissor",
     [](FuzzInput& in, ClientMemory&) { glScissor(in.integer(-8, 32), in.integer(-8, 32), in.integer(0, 64), in.integer(0, 64)); }},
    {"glDepthRange", [](FuzzInput& in, ClientMemory&) { glDepthRange(in.real_d(), in.real_d()); }},
    {"glMatrixMode", [](FuzzInput& in, ClientMemory&) { glMatrixMode(in.enumeration(kMatrixModes)); }},
    {"glLoadIdentity", [](FuzzInput&, ClientMemory&) { glLoadIdentity(); }},
    {"glPushMatrix", [](FuzzInput&, ClientMemory&) { glPushMatrix(); }},
    {"glPopMatrix", [](FuzzInput&, ClientMemory&) { glPopMatrix(); }},
    {"glOrtho",
     [](FuzzInput& in, ClientMemory&) {
       glOrtho(in.real_d() * 8, in.real_d() * 8, in.real_d() * 8, in.real_d() * 8, in.real_d(), in.real_d());
     }},
    {"glFrustum",
     [](FuzzInput& in, ClientMemory&) {
       glFrustum(in.real_d(), in.real_d(), in.real_d(), in.real_d(), in.real_d(), in.real_d());
     }},
    {"glRotatef", [](FuzzInput& in, ClientMemory&) { glRotatef(in.real() * 90, in.real(), in.real(), in.real()); }},
    {"glScalef", [](FuzzInput& in, ClientMemory&) { glScalef(in.real(), in.real(), in.real()); }},
    {"glTranslatef", [](FuzzInput& in, ClientMemory&) { glTranslatef(in.real(), in.real(), in.real()); }},
    {"glLoadMatrixf",
     [](FuzzInput&, ClientMemory& memory) { glLoadMatrixf(reinterpret_cast<const GLfloat*>(memory.arrays.data())); }},
    {"glBlendFunc",
     [](FuzzInput& in, ClientMemory&) { glBlendFunc(in.enumeration(kBlendFactors), in.enumeration(kBlendFactors)); }},
    {"glBlendEquation", blend_equation<glBlendEquation>},
    {"glBlendEquationEXT", blend_equation<glBlendEquationEXT>},
    {"glDepthFunc", [](FuzzInput& in, ClientMemory&) { glDepthFunc(in.enumeration(kCompare)); }},
    {"glAlphaFunc", [](FuzzInput& in, ClientMemory&) { glAlphaFunc(in.enumeration(kCompare), in.unit()); }},
    {"glStencilFunc",
     [](FuzzInput& in, ClientMemory&) {
       glStencilFunc(in.enumeration(kCompare), in.integer(-2, 300), GLuint(in.integer(0, 255)));
     }},
    {"glStencilOp",
     [](FuzzInput& in, ClientMemory&) {
       glStencilOp(in.enumeration(kStencilOps), in.enumeration(kStencilOps), in.enumeration(kStencilOps));
     }},
    {"glStencilFuncSeparate",
     [](FuzzInput& in, ClientMemory&) {
       glStencilFuncSeparate(in.enumeration(kFaces), in.enumeration(kCompare), in.integer(-2, 300),
                             GLuint(in.integer(0, 255)));
     }},
    {"glStencilOpSeparate", stencil_op_separate<glStencilOpSeparate>},
    {"glStencilOpSeparateATI", stencil_op_separate<glStencilOpSeparateATI>},
    {"glStencilMaskSeparate",
     [](FuzzInput& in, ClientMemory&) { glStencilMaskSeparate(in.enumeration(kFaces), GLuint(in.integer(0, 255))); }},
    {"glDrawBuffers",
     [](FuzzInput& in, ClientMemory&) {
       GLenum bufs[5];
       for (GLenum& b : bufs) b = in.enumeration({GL_NONE, GL_FRONT_LEFT, GL_BACK_LEFT, GL_FRONT, GL_AUX0});
       glDrawBuffers(in.integer(-1, 5), bufs);
     }},
    {"glTexEnvi(POINT_SPRITE)",
     [](FuzzInput& in, ClientMemory&) { glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, in.integer(-1, 2)); }},
    {"glPointParameteri(POINT_SPRITE_COORD_ORIGIN)",
     [](FuzzInput& in, ClientMemory&) {
       glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GLint(in.enumeration({GL_LOWER_LEFT, GL_UPPER_LEFT})));
     }},
    {"glLogicOp",
     [](FuzzInput& in, ClientMemory&) { glLogicOp(in.enumeration({GL_CLEAR, GL_XOR, GL_COPY_INVERTED, GL_NAND})); }},
    {"glColorMask",
     [](FuzzInput& in, ClientMemory&) { glColorMask(in.boolean(), in.boolean(), in.boolean(), in.boolean()); }},
    {"glCullFace", [](FuzzInput& in, ClientMemory&) { glCullFace(in.enumeration(kFaces)); }},
    {"glPolygonMode",
     [](FuzzInput& in, ClientMemory&) { glPolygonMode(in.enumeration(kFaces), in.enumeration({GL_POINT, GL_LINE, GL_FILL})); }},
    {"glPolygonOffset", [](FuzzInput& in, ClientMemory&) { glPolygonOffset(in.real(), in.real()); }},
    {"glLineWidth", [](FuzzInput& in, ClientMemory&) { glLineWidth(in.real() * 4); }},
    {"glPointSize", [](FuzzInput& in, ClientMemory&) { glPointSize(in.real() * 4); }},
    {"glLineStipple",
     [](FuzzInput& in, ClientMemory&) { glLineStipple(in.integer(0, 300), GLushort(in.integer(0, 0xffff))); }},
    {"glPolygonStipple",
     [](FuzzInput&, ClientMemory& memory) {
       const void* mask = memory.image_source(image_footprint(false, 32, 32, 1), false);
       if (mask) glPolygonStipple(static_cast<const GLubyte*>(mask));
     }},
    {"glPointParameterf",
     [](FuzzInput& in, ClientMemory&) {
       glPointParameterf(in.enumeration({GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE}), in.real());
     }},
    {"glShadeModel", [](FuzzInput& in, ClientMemory&) { glShadeModel(in.enumeration({GL_FLAT, GL_SMOOTH})); }},
    {"glLightfv",
     [](FuzzInput& in, ClientMemory& memory) {
       glLightfv(in.enumeration({GL_LIGHT0, GL_LIGHT1, GL_LIGHT7}), in.enumeration(kLightNames),
                 reinterpret_cast<const GLfloat*>(memory.arrays.data() + in.offset(64) * 4));
     }},
    {"glLightf",
     [](FuzzInput& in, ClientMemory&) { glLightf(in.enumeration({GL_LIGHT0, GL_LIGHT2}), in.enumeration(kLightNames), in.real() * 30); }},
    {"glLightModeli",
     [](FuzzInput& in, ClientMemory&) {
       glLightModeli(in.enumeration({GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_COLOR_CONTROL}),
                     GLint(in.enumeration({GL_TRUE, GL_FALSE, GL_SEPARATE_SPECULAR_COLOR, GL_SINGLE_COLOR})));
     }},
    {"glMaterialfv",
     [](FuzzInput& in, ClientMemory& memory) {
       glMaterialfv(in.enumeration(kFaces), in.enumeration(kMaterialNames),
                    reinterpret_cast<const GLfloat*>(memory.arrays.data() + in.offset(64) * 4));
     }},
    {"glColorMaterial",
     [](FuzzInput& in, ClientMemory&) {
       glColorMaterial(in.enumeration(kFaces), in.enumeration(kMaterialNames));
     }},
    {"glFogf", [](FuzzInput& in, ClientMemory&) { glFogf(in.enumeration(kFogNames), in.real()); }},
    {"glFogi",
     [](FuzzInput& in, ClientMemory&) { glFogi(in.enumeration(kFogNames), GLint(in.enumeration(kFogValues))); }},
    {"glClipPlane",
     [](FuzzInput& in, ClientMemory& memory) {
       glClipPlane(in.enumeration({GL_CLIP_PLANE0, GL_CLIP_PLANE3, GL_CLIP_PLANE5}),
                   reinterpret_cast<const GLdouble*>(memory.arrays.data() + in.offset(64) * 8));
     }},
    {"glRasterPos4f",
     [](FuzzInput& in, ClientMemory&) { glRasterPos4f(in.real() * 8, in.real() * 8, in.real(), in.real()); }},
    {"glWindowPos2f", [](FuzzInput& in, ClientMemory&) { glWindowPos2f(in.real() * 8, in.real() * 8); }},
    {"glPixelStorei",
     [](FuzzInput& in, ClientMemory&) { glPixelStorei(in.enumeration(kPixelStoreNames), in.integer(0, 9)); }},
    {"glPixelStoref",
     [](FuzzInput& in, ClientMemory&) { glPixelStoref(in.enumeration(kPixelStoreNames), in.real() * 4); }},
    {"glPixelTransferf",
     [](FuzzInput& in, ClientMemory&) { glPixelTransferf(in.enumeration(kTransferNames), in.real()); }},
    {"glPixelZoom", [](FuzzInput& in, ClientMemory&) { glPixelZoom(in.real() * 2, in.real() * 2); }},
    {"glPixelMapfv",
     [](FuzzInput& in, ClientMemory& memory) {
       // Sizes above GL_MAX_PIXEL_MAP_TABLE (256) are rejected before anything is read.
       const CheckedSize size = in.checked_size(256);
       glPixelMapfv(in.enumeration(kPixelMaps), size.huge ? size.value : std::min(size.value, 256),
                    reinterpret_cast<const GLfloat*>(memory.arrays.data()));
     }},
    {"glPixelMapusv",
     [](FuzzInput& in, ClientMemory& memory) {
       const CheckedSize size = in.checked_size(256);
       glPixelMapusv(in.enumeration(kPixelMaps), size.value, reinterpret_cast<const GLushort*>(memory.arrays.data()));
     }},
    {"glGetPixelMapfv",
     [](FuzzInput& in, ClientMemory&) {
       std::vector<GLfloat> out(256);
       glGetPixelMapfv(in.enumeration(kPixelMaps), out.data());
     }},
    {"glDrawPixels",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLsizei w = in.bounded_size(40), h = in.bounded_size(40);
       const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
       const void* pixels = memory.image_source(image_footprint(false, w, h, 1), w < 0 || h < 0);
       glDrawPixels(w, h, format, type, pixels);
     }},
    {"glReadPixels",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLint x = in.integer(-8, 40), y = in.integer(-8, 40);
       const GLsizei w = in.bounded_size(40), h = in.bounded_size(40);
       const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
       const size_t bytes = image_footprint(true, w, h, 1);
       if (bytes > (size_t(1) << 24)) return;
       std::vector<uint8_t> out(std::max<size_t>(bytes, 1));
       glReadPixels(x, y, w, h, format, type, memory.image_destination(out));
     }},
    {"glCopyPixels",
     [](FuzzInput& in, ClientMemory&) {
       glCopyPixels(in.integer(-8, 40), in.integer(-8, 40), in.bounded_size(40), in.bounded_size(40),
                    in.enumeration({GL_COLOR, GL_DEPTH, GL_STENCIL}));
     }},
    {"glBitmap",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLsizei w = in.bounded_size(40), h = in.bounded_size(40);
       const void* bits = memory.image_source(image_footprint(false, w, h, 1), w < 0 || h < 0);
       glBitmap(w, h, in.real(), in.real(), in.real(), in.real(), static_cast<const GLubyte*>(bits));
     }},
    {"glGenTextures",
     [](FuzzInput& in, ClientMemory&) {
       GLuint names[8];
       glGenTextures(in.bounded_size(8), names);
     }},
    {"glBindTexture", [](FuzzInput& in, ClientMemory&) { glBindTexture(in.enumeration(kBindTargets), in.name()); }},
    {"glDeleteTextures",
     [](FuzzInput& in, ClientMemory&) {
       const GLuint names[2] = {in.name(), in.name()};
       glDeleteTextures(in.bounded_size(2), names);
     }},
    {"glActiveTexture", active_texture<glActiveTexture>},
    {"glActiveTextureARB", active_texture<glActiveTextureARB>},
    {"glClientActiveTexture", client_active_texture<glClientActiveTexture>},
    {"glClientActiveTextureARB", client_active_texture<glClientActiveTextureARB>},
    {"glTexImage1D",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum target = in.enumeration(kImage1DTargets);
       const GLint level = in.integer(0, 4), internal_format = GLint(in.enumeration(kInternalFormats));
       const CheckedSize w = in.checked_size(17);
       const GLint border = in.integer(0, 1);
       const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
       glTexImage1D(target, level, internal_format, w.value, border, format, type,
                    memory.image_source(image_footprint(false, w.value, 1, 1), w.huge));
     }},
    {"glTexImage2D", tex_image_2d},
    {"glTexImage2D", tex_image_2d},
    {"glTexImage3D", tex_image_3d},
    {"glTexSubImage2D",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum target = in.enumeration({GL_TEXTURE_2D, GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_CUBE_MAP_NEGATIVE_Y});
       const GLint level = in.integer(0, 4), x = in.integer(-1, 8), y = in.integer(-1, 8);
       const CheckedSize w = in.checked_size(17), h = in.checked_size(17);
       const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
       glTexSubImage2D(target, level, x, y, w.value, h.value, format, type,
                       memory.image_source(image_footprint(false, w.value, h.value, 1), w.huge || h.huge));
     }},
    {"glTexSubImage3D",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLint level = in.integer(0, 3), x = in.integer(-1, 4), y = in.integer(-1, 4), z = in.integer(-1, 4);
       const CheckedSize w = in.checked_size(9), h = in.checked_size(9), d = in.checked_size(9);
       const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
       glTexSubImage3D(in.enumeration(kImage3DTargets), level, x, y, z, w.value, h.value, d.value, format, type,
                       memory.image_source(image_footprint(false, w.value, h.value, d.value), w.huge || h.huge || d.huge));
     }},
    {"glCopyTexImage2D",
     [](FuzzInput& in, ClientMemory&) {
       const CheckedSize w = in.checked_size(40), h = in.checked_size(40);
       glCopyTexImage2D(in.enumeration(kImage2DTargets), in.integer(0, 4), in.enumeration(kInternalFormats),
                        in.integer(-8, 40), in.integer(-8, 40), w.value, h.value, in.integer(0, 1));
     }},
    {"glCopyTexSubImage2D",
     [](FuzzInput& in, ClientMemory&) {
       glCopyTexSubImage2D(in.enumeration(kImage2DTargets), in.integer(0, 4), in.integer(-1, 8), in.integer(-1, 8),
                           in.integer(-8, 40), in.integer(-8, 40), in.bounded_size(40), in.bounded_size(40));
     }},
    {"glGetTexImage",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum target = in.enumeration({GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP_POSITIVE_X});
       const GLint level = in.integer(0, 4);
       const GLenum format = in.enumeration(kFormats), type = in.enumeration(kTypes);
       GLint w = 0, h = 0, d = 0;
       glGetTexLevelParameteriv(target, level, GL_TEXTURE_WIDTH, &w);
       glGetTexLevelParameteriv(target, level, GL_TEXTURE_HEIGHT, &h);
       glGetTexLevelParameteriv(target, level, GL_TEXTURE_DEPTH, &d);
       const size_t bytes = image_footprint(true, w, h, d);
       if (bytes > (size_t(1) << 24)) return;
       std::vector<uint8_t> out(std::max<size_t>(bytes, 1));
       glGetTexImage(target, level, format, type, memory.image_destination(out));
     }},
    {"glTexParameteri",
     [](FuzzInput& in, ClientMemory&) {
       const GLint value = in.boolean() ? GLint(in.enumeration(kTexParamValues)) : in.integer(-2, 16);
       glTexParameteri(in.enumeration(kBindTargets), in.enumeration(kTexParamNames), value);
     }},
    {"glTexParameterfv",
     [](FuzzInput& in, ClientMemory& memory) {
       glTexParameterfv(in.enumeration(kBindTargets), in.enumeration(kTexParamNames),
                        reinterpret_cast<const GLfloat*>(memory.arrays.data() + in.offset(64) * 4));
     }},
    {"glCopyBufferSubData",
     [](FuzzInput& in, ClientMemory&) {
       glCopyBufferSubData(in.enumeration(kBufferTargets), in.enumeration(kBufferTargets), in.integer(-4, 64),
                           in.integer(-4, 64), in.integer(-4, 80));
     }},
    // GL_ARB_sampler_objects: names live and stale, units in and past the range.
    {"glGenSamplers",
     [](FuzzInput& in, ClientMemory&) {
       GLuint names[2] = {};
       glGenSamplers(in.bounded_size(2), names);
     }},
    {"glDeleteSamplers",
     [](FuzzInput& in, ClientMemory&) {
       const GLuint names[2] = {in.name(), in.name()};
       glDeleteSamplers(in.bounded_size(2), names);
     }},
    {"glBindSampler", [](FuzzInput& in, ClientMemory&) { glBindSampler(GLuint(in.integer(-1, 9)), in.name()); }},
    {"glSamplerParameteri",
     [](FuzzInput& in, ClientMemory&) {
       const GLint value = in.boolean() ? GLint(in.enumeration(kTexParamValues)) : in.integer(-2, 16);
       glSamplerParameteri(in.name(), in.enumeration(kTexParamNames), value);
     }},
    {"glSamplerParameterfv",
     [](FuzzInput& in, ClientMemory& memory) {
       glSamplerParameterfv(in.name(), in.enumeration(kTexParamNames),
                            reinterpret_cast<const GLfloat*>(memory.arrays.data() + in.offset(64) * 4));
     }},
    {"glGetSamplerParameteriv",
     [](FuzzInput& in, ClientMemory&) {
       GLint values[4] = {};
       glGetSamplerParameteriv(in.name(), in.enumeration(kTexParamNames), values);
     }},
    {"glTexEnvi",
     [](FuzzInput& in, ClientMemory&) {
       glTexEnvi(in.enumeration({GL_TEXTURE_ENV, GL_TEXTURE_FILTER_CONTROL}), in.enumeration(kTexEnvNames),
                 in.boolean() ? GLint(in.enumeration(kTexEnvValues)) : in.integer(0, 4));
     }},
    {"glTexGeni",
     [](FuzzInput& in, ClientMemory&) {
       glTexGeni(in.enumeration(kCoords), in.enumeration(kTexGenNames), GLint(in.enumeration(kTexGenModes)));
     }},
    {"glTexGenfv",
     [](FuzzInput& in, ClientMemory& memory) {
       glTexGenfv(in.enumeration(kCoords), in.enumeration(kTexGenNames),
                  reinterpret_cast<const GLfloat*>(memory.arrays.data() + in.offset(64) * 4));
     }},
    {"glGetTexLevelParameteriv",
     [](FuzzInput& in, ClientMemory&) {
       GLint v[4];
       glGetTexLevelParameteriv(in.enumeration(kImage2DTargets), in.integer(-1, 20),
                                in.enumeration({GL_TEXTURE_WIDTH, GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_COMPRESSED_IMAGE_SIZE}), v);
     }},
    {"glNewList",
     [](FuzzInput& in, ClientMemory& memory) {
       // Inside a list glNewList fails: the list being compiled keeps its count.
       if (!compiling_list()) memory.calls_to_lists_in_list = 0;
       glNewList(in.name(), in.enumeration({GL_COMPILE, GL_COMPILE_AND_EXECUTE}));
     }},
    {"glEndList", [](FuzzInput&, ClientMemory&) { glEndList(); }},
    {"glCallList",
     [](FuzzInput& in, ClientMemory& memory) {
       if (may_call_lists(memory)) glCallList(in.name());
     }},
    {"glCallLists",
     [](FuzzInput& in, ClientMemory& memory) {
       const bool compiling = compiling_list();
       if (!may_call_lists(memory)) return;
       const GLsizei n = compiling ? std::min(in.bounded_size(1), 1) : in.bounded_size(8);
       glCallLists(n, in.enumeration({GL_UNSIGNED_BYTE, GL_INT, GL_FLOAT, GL_2_BYTES, GL_4_BYTES}), memory.arrays.data());
     }},
    {"glGenLists", [](FuzzInput& in, ClientMemory&) { glGenLists(in.bounded_size(16)); }},
    {"glDeleteLists", [](FuzzInput& in, ClientMemory&) { glDeleteLists(in.name(), in.integer(-1, 16)); }},
    {"glListBase", [](FuzzInput& in, ClientMemory&) { glListBase(GLuint(in.integer(0, 8))); }},
    {"glVertexPointer",
     [](FuzzInput& in, ClientMemory& memory) {
       glVertexPointer(in.integer(2, 4), in.enumeration(kArrayTypes), array_stride(in), array_pointer(in, memory));
     }},
    {"glColorPointer",
     [](FuzzInput& in, ClientMemory& memory) {
       glColorPointer(in.integer(3, 4), in.enumeration(kArrayTypes), array_stride(in), array_pointer(in, memory));
     }},
    {"glNormalPointer",
     [](FuzzInput& in, ClientMemory& memory) {
       glNormalPointer(in.enumeration(kArrayTypes), array_stride(in), array_pointer(in, memory));
     }},
    {"glTexCoordPointer",
     [](FuzzInput& in, ClientMemory& memory) {
       glTexCoordPointer(in.integer(1, 4), in.enumeration(kArrayTypes), array_stride(in), array_pointer(in, memory));
     }},
    {"glIndexPointer",
     [](FuzzInput& in, ClientMemory& memory) {
       glIndexPointer(in.enumeration(kArrayTypes), array_stride(in), array_pointer(in, memory));
     }},
    {"glEdgeFlagPointer",
     [](FuzzInput& in, ClientMemory& memory) { glEdgeFlagPointer(array_stride(in), array_pointer(in, memory)); }},
    {"glFogCoordPointer",
     [](FuzzInput& in, ClientMemory& memory) {
       glFogCoordPointer(in.enumeration({GL_FLOAT, GL_DOUBLE}), array_stride(in), array_pointer(in, memory));
     }},
    {"glSecondaryColorPointer",
     [](FuzzInput& in, ClientMemory& memory) {
       glSecondaryColorPointer(3, in.enumeration(kArrayTypes), array_stride(in), array_pointer(in, memory));
     }},
    {"glInterleavedArrays",
     [](FuzzInput& in, ClientMemory& memory) {
       glInterleavedArrays(in.enumeration({GL_V2F, GL_C4UB_V3F, GL_T2F_C4F_N3F_V3F, GL_T4F_V4F, GL_N3F_V3F}),
                           array_stride(in), array_pointer(in, memory));
     }},
    {"glEnableClientState", [](FuzzInput& in, ClientMemory&) { glEnableClientState(in.enumeration(kClientArrays)); }},
    {"glDisableClientState", [](FuzzInput& in, ClientMemory&) { glDisableClientState(in.enumeration(kClientArrays)); }},
    {"glArrayElement", array_element<glArrayElement>},
    {"glArrayElementEXT", array_element<glArrayElementEXT>},
    {"glDrawArrays", draw_arrays<glDrawArrays>},
    {"glDrawArraysEXT", draw_arrays<glDrawArraysEXT>},
    {"glDrawElements",
     [](FuzzInput& in, ClientMemory&) {
       const GLenum mode = in.enumeration(kPrimitives), type = in.enumeration(kIndexTypes);
       const GLsizei count = in.bounded_size(64);
       const std::vector<uint8_t> indices = index_bytes(in, type, count);
       glDrawElements(mode, count, type, indices.data());
     }},
    {"glDrawRangeElements", draw_range_elements<glDrawRangeElements>},
    {"glDrawRangeElementsEXT", draw_range_elements<glDrawRangeElementsEXT>},
    {"glMultiDrawArrays", multi_draw_arrays<glMultiDrawArrays>},
    {"glMultiDrawArraysEXT", multi_draw_arrays<glMultiDrawArraysEXT>},
    {"glGenBuffers", gen_names<glGenBuffers, 8>},
    {"glGenBuffersARB", gen_names<glGenBuffersARB, 8>},
    {"glBindBuffer", bind_buffer<glBindBuffer>},
    {"glBindBufferARB", bind_buffer<glBindBufferARB>},
    {"glBufferData", buffer_data<glBufferData>},
    {"glBufferDataARB", buffer_data<glBufferDataARB>},
    {"glBufferSubData", buffer_sub_data<glBufferSubData>},
    {"glBufferSubDataARB", buffer_sub_data<glBufferSubDataARB>},
    {"glGetBufferSubData", get_buffer_sub_data<glGetBufferSubData>},
    {"glGetBufferSubDataARB", get_buffer_sub_data<glGetBufferSubDataARB>},
    {"glMapBuffer", map_buffer<glMapBuffer>},
    {"glMapBufferARB", map_buffer<glMapBufferARB>},
    {"glMapBufferRange", map_buffer_range},
    {"glFlushMappedBufferRange",
     [](FuzzInput& in, ClientMemory&) {
       glFlushMappedBufferRange(in.enumeration(kBufferTargets), in.integer(-4, 64), in.integer(-4, 80));
     }},
    {"glUnmapBuffer", unmap_buffer<glUnmapBuffer>},
    {"glUnmapBufferARB", unmap_buffer<glUnmapBufferARB>},
    {"glDeleteBuffers", delete_buffers<glDeleteBuffers>},
    {"glDeleteBuffersARB", delete_buffers<glDeleteBuffersARB>},
    // A vertex array object's arrays start disabled with null pointers (GL reads none of them);
    // the fuzzer's pointers go into whichever object is bound.
    {"glGenVertexArrays", gen_names<glGenVertexArrays, 4>},
    {"glBindVertexArray", [](FuzzInput& in, ClientMemory&) { glBindVertexArray(in.name()); }},
    {"glDeleteVertexArrays", delete_names<glDeleteVertexArrays>},
    {"glGenVertexArraysOES", gen_names<glGenVertexArraysOES, 4>},
    {"glBindVertexArrayOES", [](FuzzInput& in, ClientMemory&) { glBindVertexArrayOES(in.name()); }},
    {"glDeleteVertexArraysOES", delete_names<glDeleteVertexArraysOES>},
    {"glIsVertexArrayOES", [](FuzzInput& in, ClientMemory&) { glIsVertexArrayOES(in.name()); }},
    {"glMap1f",
     [](FuzzInput& in, ClientMemory& memory) {
       // stride * order floats are read: at most 40 * 31 of the 16384 floats there.
       glMap1f(in.enumeration(kMap1Targets), in.real(), in.real(), in.integer(0, 40) % 41, in.integer(0, 31),
               reinterpret_cast<const GLfloat*>(memory.arrays.data()));
     }},
    {"glMap2f",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLint ustride = in.integer(0, 8) % 9, uorder = in.integer(0, 31);
       const GLint vstride = in.integer(0, 8 * 31) % 249, vorder = in.integer(0, 31);
       glMap2f(in.enumeration(kMap2Targets), in.real(), in.real(), ustride, uorder, in.real(), in.real(), vstride,
               vorder, reinterpret_cast<const GLfloat*>(memory.arrays.data()));
     }},
    {"glMapGrid2f",
     [](FuzzInput& in, ClientMemory&) {
       glMapGrid2f(in.integer(0, 16), in.real(), in.real(), in.integer(0, 16), in.real(), in.real());
     }},
    {"glEvalMesh2",
     [](FuzzInput& in, ClientMemory&) {
       const GLenum mode = in.enumeration({GL_POINT, GL_LINE, GL_FILL});
       const GLint i1 = in.integer(-2, 16), i2 = mesh_end(i1, in.integer(-2, 16));
       const GLint j1 = in.integer(-2, 16), j2 = mesh_end(j1, in.integer(-2, 16));
       glEvalMesh2(mode, i1, i2, j1, j2);
     }},
    {"glEvalCoord2f", [](FuzzInput& in, ClientMemory&) { glEvalCoord2f(in.real(), in.real()); }},
    {"glEvalPoint1", [](FuzzInput& in, ClientMemory&) { glEvalPoint1(in.integer(-2, 16)); }},
    {"glRenderMode",
     [](FuzzInput& in, ClientMemory&) { glRenderMode(in.enumeration({GL_RENDER, GL_SELECT, GL_FEEDBACK})); }},
    {"glFeedbackBuffer",
     [](FuzzInput& in, ClientMemory& memory) {
       glFeedbackBuffer(in.bounded_size(GLsizei(memory.feedback.size())),
                        in.enumeration({GL_2D, GL_3D_COLOR, GL_4D_COLOR_TEXTURE}), memory.feedback.data());
     }},
    {"glSelectBuffer",
     [](FuzzInput& in, ClientMemory& memory) {
       glSelectBuffer(in.bounded_size(GLsizei(memory.selection.size())), memory.selection.data());
     }},
    {"glInitNames", [](FuzzInput&, ClientMemory&) { glInitNames(); }},
    {"glPushName", [](FuzzInput& in, ClientMemory&) { glPushName(in.name()); }},
    {"glPopName", [](FuzzInput&, ClientMemory&) { glPopName(); }},
    {"glAccum",
     [](FuzzInput& in, ClientMemory&) {
       glAccum(in.enumeration({GL_ACCUM, GL_LOAD, GL_RETURN, GL_MULT, GL_ADD}), in.real());
     }},
    {"glPushAttrib", [](FuzzInput& in, ClientMemory&) { glPushAttrib(in.boolean() ? GL_ALL_ATTRIB_BITS : GLbitfield(in.integer(0, 1 << 20))); }},
    {"glPopAttrib", [](FuzzInput&, ClientMemory&) { glPopAttrib(); }},
    {"glPushClientAttrib", [](FuzzInput&, ClientMemory&) { glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS); }},
    {"glPopClientAttrib", [](FuzzInput&, ClientMemory&) { glPopClientAttrib(); }},
    {"glGenQueries", gen_names<glGenQueries, 4>},
    {"glGenQueriesARB", gen_names<glGenQueriesARB, 4>},
    {"glBeginQuery", begin_query<glBeginQuery>},
    {"glBeginQueryARB", begin_query<glBeginQueryARB>},
    {"glEndQuery", end_query<glEndQuery>},
    {"glEndQueryARB", end_query<glEndQueryARB>},
    {"glGetQueryObjectuiv", get_query_objectuiv<glGetQueryObjectuiv>},
    {"glGetQueryObjectuivARB", get_query_objectuiv<glGetQueryObjectuivARB>},
    {"glGetFloatv",
     [](FuzzInput& in, ClientMemory&) {
       GLfloat out[64];
       glGetFloatv(in.enumeration(kGetNames), out);
     }},
    {"glGetIntegerv",
     [](FuzzInput& in, ClientMemory&) {
       GLint out[64];
       glGetIntegerv(in.enumeration(kGetNames), out);
     }},
    {"glGetString", [](FuzzInput& in, ClientMemory&) { glGetString(in.enumeration({GL_VENDOR, GL_VERSION, GL_EXTENSIONS})); }},
    {"glGetError", [](FuzzInput&, ClientMemory&) { glGetError(); }},
    {"glFlush", [](FuzzInput&, ClientMemory&) { glFlush(); }},
    {"glFinish", [](FuzzInput&, ClientMemory&) { glFinish(); }},
};

}  // namespace

std::span<const GlCall> gl_calls() {
  static const std::vector<GlCall> calls = [] {
    std::vector<GlCall> all(std::begin(kCalls), std::end(kCalls));
    for (std::span<const GlCall> more :
         {program_calls(), uniform_calls(), framebuffer_calls(), query_calls(), variant_calls(), es1_calls(),
          get_calls(), texture_image_calls(), parameter_calls(), debug_calls(), robustness_calls(), vertex_array_ext_calls(), egl_calls()})
      all.insert(all.end(), more.begin(), more.end());
    return all;
  }();
  return calls;
}

}  // namespace pineda::fuzz
