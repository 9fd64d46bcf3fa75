// The fuzzed GL 1.x-2.0 queries the other tables leave out: context state as booleans and
// doubles, lights, materials, texture parameters and coordinate generation as floats,
// evaluator maps, pixel maps, the polygon stipple, pointers, clip planes, query objects and
// glIsEnabled. Each writes into memory exactly as large as the query's values (sized_query.h),
// or an image footprint under the pack state where the query packs pixels.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <vector>

#include "tests/fuzz/gl_calls.h"
#include "tests/fuzz/gl_enum_lists.h"
#include "tests/fuzz/object_names.h"
#include "tests/fuzz/sized_query.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kImageTargets[] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                                    GL_PROXY_TEXTURE_2D, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_RECTANGLE_ARB,
                                    GL_PROXY_TEXTURE_RECTANGLE_ARB};
constexpr QueryName kTexLevelQueries[] = {{GL_TEXTURE_WIDTH, 1},       {GL_TEXTURE_DEPTH, 1},
                                          {GL_TEXTURE_BORDER, 1},      {GL_TEXTURE_INTERNAL_FORMAT, 1},
                                          {GL_TEXTURE_RED_SIZE, 1},    {GL_TEXTURE_COMPRESSED, 1},
                                          {GL_TEXTURE_COMPRESSED_IMAGE_SIZE, 1}};
constexpr GLenum kMapTargets[] = {GL_MAP1_VERTEX_3, GL_MAP1_VERTEX_4, GL_MAP1_COLOR_4, GL_MAP1_INDEX,
                                  GL_MAP2_VERTEX_3, GL_MAP2_NORMAL,   GL_MAP2_TEXTURE_COORD_4};
constexpr GLenum kPixelMaps[] = {GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_I_TO_A,
                                 GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G, GL_PIXEL_MAP_A_TO_A};
constexpr GLenum kPointerNames[] = {GL_VERTEX_ARRAY_POINTER,     GL_COLOR_ARRAY_POINTER,
                                    GL_TEXTURE_COORD_ARRAY_POINTER, GL_FOG_COORD_ARRAY_POINTER,
                                    GL_FEEDBACK_BUFFER_POINTER,  GL_SELECTION_BUFFER_POINTER,
                                    GL_EDGE_FLAG_ARRAY_POINTER,  GL_SECONDARY_COLOR_ARRAY_POINTER};
constexpr QueryName kIndexedQueries[] = {{GL_BLEND, 1}, {GL_COLOR_WRITEMASK, 4}, {GL_DRAW_BUFFER0, 1}};
constexpr GLenum kCapabilities[] = {GL_BLEND,       GL_DEPTH_TEST,      GL_LIGHTING,     GL_LIGHT7,
                                    GL_TEXTURE_2D,  GL_CLIP_PLANE5,     GL_MAP2_VERTEX_4, GL_VERTEX_ARRAY,
                                    GL_POINT_SPRITE, GL_TEXTURE_GEN_Q,  GL_COLOR_SUM,    GL_MULTISAMPLE};

// The values a map query writes: 1 or 2 for GL_ORDER, 2 or 4 for GL_DOMAIN, the control
// points (order(s) times the map's components, at most 4) for GL_COEFF.
size_t map_values(GLenum target, GLenum query) {
  const bool two_dimensional = target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4;
  if (query == GL_ORDER) return two_dimensional ? 2 : 1;
  if (query == GL_DOMAIN) return two_dimensional ? 4 : 2;
  if (query != GL_COEFF) return 0;
  GLint order[2] = {0, 0};
  glGetMapiv(target, GL_ORDER, order);
  return size_t(std::max(order[0], 0)) * (two_dimensional ? size_t(std::max(order[1], 0)) : 1) * 4;
}

template <typename T>
void get_map(FuzzInput& in, void (*get)(GLenum, GLenum, T*)) {
  const GLenum target = in.enumeration(kMapTargets), query = in.enumeration({GL_COEFF, GL_ORDER, GL_DOMAIN});
  std::vector<T> out(std::max<size_t>(map_values(target, query), 1));
  get(target, query, out.data());
}

// With a pixel pack buffer bound, the values go there at the buffer offset.
template <typename T>
void get_pixel_map(FuzzInput& in, ClientMemory& memory, void (*get)(GLenum, T*)) {
  const GLenum map = in.enumeration(kPixelMaps);
  GLint size = 0;
  glGetIntegerv(map - GL_PIXEL_MAP_I_TO_I + GL_PIXEL_MAP_I_TO_I_SIZE, &size);
  std::vector<uint8_t> out(std::max<size_t>(size_t(std::max(size, 0)) * sizeof(T), 1));
  get(map, static_cast<T*>(memory.image_destination(out)));
}

template <typename T>
void get_tex_gen(FuzzInput& in, void (*get)(GLenum, GLenum, T*)) {
  sized_get(in, get, kTexGenCoords, kTexGenQueries);
}

// The calls that have ARB or EXT names take the call as a template argument.
template <auto Get>
void get_query(FuzzInput& in, ClientMemory&) {
  GLint value = 0;
  const GLenum target = in.enumeration({GL_SAMPLES_PASSED});
  Get(target, in.enumeration({GL_CURRENT_QUERY, GL_QUERY_COUNTER_BITS}), &value);
}

template <auto Get>
void get_query_object(FuzzInput& in, ClientMemory&) {
  GLint value = 0;
  const GLuint query = in.name();
  Get(query, in.enumeration({GL_QUERY_RESULT, GL_QUERY_RESULT_AVAILABLE}), &value);
}

template <auto Get>
void get_pointer(FuzzInput& in, ClientMemory&) {
  void* pointer = nullptr;
  Get(in.enumeration(kPointerNames), &pointer);
}

template <auto Get>
void get_buffer_pointer(FuzzInput& in, ClientMemory&) {
  void* pointer = nullptr;
  const GLenum target = in.enumeration({GL_ARRAY_BUFFER, GL_PIXEL_PACK_BUFFER, GL_PIXEL_UNPACK_BUFFER});
  Get(target, in.enumeration({GL_BUFFER_MAP_POINTER}), &pointer);
}

// EXT_draw_buffers2: per draw buffer, the blend enable (1 value) or the colour mask (4 values).
template <typename T>
void get_indexed(FuzzInput& in, void (*get)(GLenum, GLuint, T*)) {
  const QueryName query = query_name(in, kIndexedQueries);
  std::vector<T> out(query.count);
  get(query.name, GLuint(in.integer(0, 8)), out.data());
}

const GlCall kCalls[] = {
    {"glGetBooleanv", [](FuzzInput& in, ClientMemory&) { get_state(in, glGetBooleanv); }},
    {"glGetDoublev", [](FuzzInput& in, ClientMemory&) { get_state(in, glGetDoublev); }},
    {"glGetLightfv", [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetLightfv, kLights, kLightQueries); }},
    {"glGetMaterialfv",
     [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetMaterialfv, kMaterialFaces, kMaterialQueries); }},
    {"glGetTexGenfv", [](FuzzInput& in, ClientMemory&) { get_tex_gen(in, glGetTexGenfv); }},
    {"glGetTexGendv", [](FuzzInput& in, ClientMemory&) { get_tex_gen(in, glGetTexGendv); }},
    {"glGetTexParameterfv",
     [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetTexParameterfv, kTextureTargets, kTexParameterQueries); }},
    {"glGetTexLevelParameterfv",
     [](FuzzInput& in, ClientMemory&) {
       const GLenum target = in.enumeration(kImageTargets);
       const GLint level = in.integer(-1, 14);
       GLfloat value = 0;
       glGetTexLevelParameterfv(target, level, query_name(in, kTexLevelQueries).name, &value);
     }},
    {"glGetClipPlane", [](FuzzInput& in, ClientMemory&) { get_clip_plane(in, glGetClipPlane); }},
    {"glGetMapdv", [](FuzzInput& in, ClientMemory&) { get_map(in, glGetMapdv); }},
    {"glGetMapfv", [](FuzzInput& in, ClientMemory&) { get_map(in, glGetMapfv); }},
    {"glGetMapiv", [](FuzzInput& in, ClientMemory&) { get_map(in, glGetMapiv); }},
    {"glGetPixelMapuiv", [](FuzzInput& in, ClientMemory& memory) { get_pixel_map(in, memory, glGetPixelMapuiv); }},
    {"glGetPixelMapusv", [](FuzzInput& in, ClientMemory& memory) { get_pixel_map(in, memory, glGetPixelMapusv); }},
    {"glGetPolygonStipple",
     [](FuzzInput&, ClientMemory& memory) {
       const size_t bytes = image_footprint(true, 32, 32, 1);
       if (bytes > (size_t(1) << 24)) return;  // the pack state unknown (between glBegin and glEnd)
       std::vector<uint8_t> out(bytes);
       glGetPolygonStipple(static_cast<GLubyte*>(memory.image_destination(out)));
     }},
    {"glGetPointerv", get_pointer<glGetPointerv>},
    {"glGetPointervEXT", get_pointer<glGetPointervEXT>},
    {"glGetBufferPointerv", get_buffer_pointer<glGetBufferPointerv>},
    {"glGetBufferPointervARB", get_buffer_pointer<glGetBufferPointervARB>},
    {"glGetBufferParameterivARB",
     [](FuzzInput& in, ClientMemory&) {
       GLint value = 0;
       const GLenum target = in.enumeration({GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER, GL_PIXEL_PACK_BUFFER});
       glGetBufferParameterivARB(target, in.enumeration({GL_BUFFER_SIZE, GL_BUFFER_USAGE, GL_BUFFER_MAPPED}), &value);
     }},
    {"glGetBooleanIndexedvEXT", [](FuzzInput& in, ClientMemory&) { get_indexed(in, glGetBooleanIndexedvEXT); }},
    {"glGetIntegerIndexedvEXT", [](FuzzInput& in, ClientMemory&) { get_indexed(in, glGetIntegerIndexedvEXT); }},
    {"glGetQueryiv", get_query<glGetQueryiv>},
    {"glGetQueryivARB", get_query<glGetQueryivARB>},
    {"glGetQueryObjectiv", get_query_object<glGetQueryObjectiv>},
    {"glGetQueryObjectivARB", get_query_object<glGetQueryObjectivARB>},
    {"glDeleteQueries", delete_names<glDeleteQueries>},
    {"glDeleteQueriesARB", delete_names<glDeleteQueriesARB>},
    {"glIsEnabled", [](FuzzInput& in, ClientMemory&) { glIsEnabled(in.enumeration(kCapabilities)); }},
    {"glGetShaderPrecisionFormat",
     [](FuzzInput& in, ClientMemory&) {
       GLint range[2], precision = 0;
       const GLenum shader = in.enumeration({GL_VERTEX_SHADER, GL_FRAGMENT_SHADER});
       glGetShaderPrecisionFormat(shader, in.enumeration({GL_LOW_FLOAT, GL_HIGH_FLOAT, GL_MEDIUM_INT}), range,
                                  &precision);
     }},
};

}  // namespace

std::span<const GlCall> get_calls() { return kCalls; }

}  // namespace pineda::fuzz
