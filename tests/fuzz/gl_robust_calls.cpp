// The fuzzed robustness calls (ARB_robustness, KHR_robustness, EXT_robustness): the reset
// status, and the queries bounded by bufSize, each into exactly bufSize bytes so that
// AddressSanitizer sees a write past it (a query whose values need more must write nothing).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <vector>

#include "tests/fuzz/es_prototypes.h"
#include "tests/fuzz/gl_calls.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kPixelMaps[] = {GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_A_TO_A};
constexpr GLenum kMapTargets[] = {GL_MAP1_VERTEX_3, GL_MAP1_COLOR_4, GL_MAP2_VERTEX_4, GL_MAP2_TEXTURE_COORD_2};

// bufSize bytes (an address even for 0), or a pixel pack buffer offset where one is bound.
struct Bounded {
  GLsizei size;
  std::vector<uint8_t> bytes;
};

Bounded bounded(FuzzInput& in, GLsizei max) {
  const GLsizei size = in.bounded_size(max);
  return {size, std::vector<uint8_t>(size_t(std::max(size, 0)) + (size <= 0))};
}

// glGetnUniform*: a location of the current program or another, into bufSize bytes.
template <typename T, typename Call>
void get_uniform_bounded(FuzzInput& in, Call call) {
  const GLuint program = in.name();
  const GLint location = in.integer(-1, 24);
  Bounded out = bounded(in, 16 * sizeof(T));
  call(program, location, out.size, reinterpret_cast<T*>(out.bytes.data()));
}

// glReadnPixels: bufSize bytes that may be less than the pixels need (then nothing is written).
template <typename Call>
void read_pixels_bounded(FuzzInput& in, ClientMemory& memory, Call call) {
  const GLint x = in.integer(-8, 40), y = in.integer(-8, 40);
  const GLsizei w = in.bounded_size(40), h = in.bounded_size(40);
  const GLenum format = in.enumeration({GL_RGBA, GL_RGB, GL_DEPTH_COMPONENT, GL_STENCIL_INDEX, GL_LUMINANCE, GL_BGRA});
  const GLenum type = in.enumeration({GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_INT, GL_BITMAP});
  Bounded out = bounded(in, 40 * 40 * 16);
  call(x, y, w, h, format, type, out.size, memory.image_destination(out.bytes));
}

template <typename Call>
void reset_status(Call call) {
  call();
}

template <typename T>
void get_map_bounded(FuzzInput& in, void (*get)(GLenum, GLenum, GLsizei, T*)) {
  const GLenum target = in.enumeration(kMapTargets), query = in.enumeration({GL_COEFF, GL_ORDER, GL_DOMAIN});
  Bounded out = bounded(in, 31 * 31 * 4 * sizeof(T));
  get(target, query, out.size, reinterpret_cast<T*>(out.bytes.data()));
}

template <typename T>
void get_pixel_map_bounded(FuzzInput& in, ClientMemory& memory, void (*get)(GLenum, GLsizei, T*)) {
  const GLenum map = in.enumeration(kPixelMaps);
  Bounded out = bounded(in, 300 * sizeof(T));
  get(map, out.size, static_cast<T*>(memory.image_destination(out.bytes)));
}

const GlCall kCalls[] = {
    {"glGetGraphicsResetStatus", [](FuzzInput&, ClientMemory&) { reset_status(glGetGraphicsResetStatus); }},
    {"glGetGraphicsResetStatusARB", [](FuzzInput&, ClientMemory&) { reset_status(glGetGraphicsResetStatusARB); }},
    {"glGetGraphicsResetStatusEXT", [](FuzzInput&, ClientMemory&) { reset_status(glGetGraphicsResetStatusEXT); }},
    {"glGetGraphicsResetStatusKHR", [](FuzzInput&, ClientMemory&) { reset_status(glGetGraphicsResetStatusKHR); }},
    {"glGetnUniformfv", [](FuzzInput& in, ClientMemory&) { get_uniform_bounded<GLfloat>(in, glGetnUniformfv); }},
    {"glGetnUniformfvARB", [](FuzzInput& in, ClientMemory&) { get_uniform_bounded<GLfloat>(in, glGetnUniformfvARB); }},
    {"glGetnUniformfvEXT", [](FuzzInput& in, ClientMemory&) { get_uniform_bounded<GLfloat>(in, glGetnUniformfvEXT); }},
    {"glGetnUniformfvKHR", [](FuzzInput& in, ClientMemory&) { get_uniform_bounded<GLfloat>(in, glGetnUniformfvKHR); }},
    {"glGetnUniformiv", [](FuzzInput& in, ClientMemory&) { get_uniform_bounded<GLint>(in, glGetnUniformiv); }},
    {"glGetnUniformivARB", [](FuzzInput& in, ClientMemory&) { get_uniform_bounded<GLint>(in, glGetnUniformivARB); }},
    {"glGetnUniformivEXT", [](FuzzInput& in, ClientMemory&) { get_uniform_bounded<GLint>(in, glGetnUniformivEXT); }},
    {"glGetnUniformivKHR", [](FuzzInput& in, ClientMemory&) { get_uniform_bounded<GLint>(in, glGetnUniformivKHR); }},
    {"glGetnUniformuiv", [](FuzzInput& in, ClientMemory&) { get_uniform_bounded<GLuint>(in, glGetnUniformuiv); }},
    {"glGetnUniformuivKHR", [](FuzzInput& in, ClientMemory&) { get_uniform_bounded<GLuint>(in, glGetnUniformuivKHR); }},
    {"glReadnPixels", [](FuzzInput& in, ClientMemory& m) { read_pixels_bounded(in, m, glReadnPixels); }},
    {"glReadnPixelsARB", [](FuzzInput& in, ClientMemory& m) { read_pixels_bounded(in, m, glReadnPixelsARB); }},
    {"glReadnPixelsEXT", [](FuzzInput& in, ClientMemory& m) { read_pixels_bounded(in, m, glReadnPixelsEXT); }},
    {"glReadnPixelsKHR", [](FuzzInput& in, ClientMemory& m) { read_pixels_bounded(in, m, glReadnPixelsKHR); }},
    {"glGetnMapdvARB", [](FuzzInput& in, ClientMemory&) { get_map_bounded(in, glGetnMapdvARB); }},
    {"glGetnMapfvARB", [](FuzzInput& in, ClientMemory&) { get_map_bounded(in, glGetnMapfvARB); }},
    {"glGetnMapivARB", [](FuzzInput& in, ClientMemory&) { get_map_bounded(in, glGetnMapivARB); }},
    {"glGetnPixelMapfvARB", [](FuzzInput& in, ClientMemory& m) { get_pixel_map_bounded(in, m, glGetnPixelMapfvARB); }},
    {"glGetnPixelMapuivARB", [](FuzzInput& in, ClientMemory& m) { get_pixel_map_bounded(in, m, glGetnPixelMapuivARB); }},
    {"glGetnPixelMapusvARB", [](FuzzInput& in, ClientMemory& m) { get_pixel_map_bounded(in, m, glGetnPixelMapusvARB); }},
    {"glGetnPolygonStippleARB",
     [](FuzzInput& in, ClientMemory& memory) {
       Bounded out = bounded(in, 200);
       glGetnPolygonStippleARB(out.size, static_cast<GLubyte*>(memory.image_destination(out.bytes)));
     }},
    {"glGetnTexImageARB",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum target = in.enumeration({GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP_POSITIVE_Z});
       const GLint level = in.integer(0, 4);
       const GLenum format = in.enumeration({GL_RGBA, GL_RGB, GL_LUMINANCE, GL_DEPTH_COMPONENT, GL_BGRA});
       const GLenum type = in.enumeration({GL_UNSIGNED_BYTE, GL_FLOAT, GL_UNSIGNED_SHORT_4_4_4_4, GL_INT});
       Bounded out = bounded(in, 17 * 17 * 16);
       glGetnTexImageARB(target, level, format, type, out.size, memory.image_destination(out.bytes));
     }},
    {"glGetnCompressedTexImageARB",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum target = in.enumeration({GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D});
       const GLint level = in.integer(0, 4);
       Bounded out = bounded(in, 64);
       glGetnCompressedTexImageARB(target, level, out.size, memory.image_destination(out.bytes));
     }},
};

}  // namespace

std::span<const GlCall> robustness_calls() { return kCalls; }

}  // namespace pineda::fuzz
