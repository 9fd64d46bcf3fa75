// The fuzzed GL 1.x state calls the GL 1.x table has in one form only: the other types of
// glLight, glMaterial, glTexEnv, glTexGen, glTexParameter and glPointParameter, the double
// evaluator maps, hints, winding, masks, glPixelMapuiv and glMultiDrawElements.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <vector>

#include "tests/fuzz/client_arrays.h"
#include "tests/fuzz/gl_enum_lists.h"
#include "tests/fuzz/typed_call.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kPixelMaps[] = {GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_G, GL_PIXEL_MAP_B_TO_B};
constexpr GLenum kPrimitives[] = {GL_POINTS, GL_LINES, GL_LINE_LOOP, GL_TRIANGLES, GL_TRIANGLE_FAN, GL_QUADS, GL_POLYGON};

// Draws of up to three index lists, each within what the client arrays hold.
void multi_draw_elements(FuzzInput& in, void (*draw)(GLenum, const GLsizei*, GLenum, const void* const*, GLsizei)) {
  const GLenum mode = in.enumeration(kPrimitives);
  const GLenum type = in.enumeration({GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT});
  const GLsizei draws = std::min(in.bounded_size(3), 3);
  GLsizei counts[3];
  std::vector<GLuint> indices[3];
  const void* lists[3];
  for (int i = 0; i < 3; ++i) {
    counts[i] = in.bounded_size(32);
    indices[i].resize(size_t(std::max(counts[i], 0)) + 1);
    for (GLuint& index : indices[i]) index = GLuint(in.integer(0, kMaxVertexIndex)) % (kMaxVertexIndex + 1);
    // Narrower types read the same values' low bytes: still indices within the arrays.
    if (type == GL_UNSIGNED_BYTE) for (GLuint& index : indices[i]) index = (index & 0xff) * 0x01010101u;
    if (type == GL_UNSIGNED_SHORT) for (GLuint& index : indices[i]) index = (index & 0x3ff) * 0x00010001u;
    lists[i] = indices[i].data();
  }
  draw(mode, counts, type, lists, draws);
}

// A 1D or 2D map read from ClientMemory: at most stride * order (times vstride * vorder) doubles.
void map1d(FuzzInput& in, ClientMemory& memory) {
  const GLenum target = in.enumeration({GL_MAP1_VERTEX_3, GL_MAP1_COLOR_4, GL_MAP1_INDEX, GL_MAP1_TEXTURE_COORD_2});
  const GLdouble u1 = in.real_d(), u2 = in.real_d();
  const GLint stride = in.integer(0, 20) % 21, order = in.integer(0, 31);
  glMap1d(target, u1, u2, stride, order, reinterpret_cast<const GLdouble*>(memory.arrays.data()));
}

void map2d(FuzzInput& in, ClientMemory& memory) {
  const GLenum target = in.enumeration({GL_MAP2_VERTEX_3, GL_MAP2_NORMAL, GL_MAP2_COLOR_4, GL_MAP2_TEXTURE_COORD_1});
  const GLint ustride = in.integer(0, 8) % 9, uorder = in.integer(0, 31);
  const GLint vstride = in.integer(0, 8 * 31) % 249, vorder = in.integer(0, 31);
  glMap2d(target, in.real_d(), in.real_d(), ustride, uorder, in.real_d(), in.real_d(), vstride, vorder,
          reinterpret_cast<const GLdouble*>(memory.arrays.data()));
}

const GlCall kCalls[] = {
    PINEDA_TYPED_CALL_AFTER2(glLighti, kLights, kLightNames),
    PINEDA_TYPED_CALL_AFTER2(glLightiv, kLights, kLightNames),
    PINEDA_TYPED_CALL_AFTER2(glMaterialf, kMaterialFaces, kMaterialNames),
    PINEDA_TYPED_CALL_AFTER2(glMateriali, kMaterialFaces, kMaterialNames),
    PINEDA_TYPED_CALL_AFTER2(glMaterialiv, kMaterialFaces, kMaterialNames),
    PINEDA_TYPED_CALL_AFTER2(glTexEnvf, kTexEnvTargets, kTexEnvNames),
    PINEDA_TYPED_CALL_AFTER2(glTexEnviv, kTexEnvTargets, kTexEnvNames),
    PINEDA_TYPED_CALL_AFTER2(glTexGend, kTexGenCoords, kTexGenNames),
    PINEDA_TYPED_CALL_AFTER2(glTexGendv, kTexGenCoords, kTexGenNames),
    PINEDA_TYPED_CALL_AFTER2(glTexGenf, kTexGenCoords, kTexGenNames),
    PINEDA_TYPED_CALL_AFTER2(glTexGeniv, kTexGenCoords, kTexGenNames),
    PINEDA_TYPED_CALL_AFTER2(glTexParameterf, kTextureTargets, kTexParameterNames),
    PINEDA_TYPED_CALL_AFTER2(glTexParameteriv, kTextureTargets, kTexParameterNames),
    PINEDA_TYPED_CALL_AFTER(glPointParameteri, kPointParameterNames),
    PINEDA_TYPED_CALL(glDepthMask),
    PINEDA_TYPED_CALL(glEdgeFlagv),
    {"glFrontFace", [](FuzzInput& in, ClientMemory&) { glFrontFace(in.enumeration({GL_CW, GL_CCW})); }},
    {"glHint",
     [](FuzzInput& in, ClientMemory&) {
       const GLenum target = in.enumeration({GL_PERSPECTIVE_CORRECTION_HINT, GL_FOG_HINT, GL_GENERATE_MIPMAP_HINT,
                                             GL_LINE_SMOOTH_HINT, GL_TEXTURE_COMPRESSION_HINT});
       glHint(target, in.enumeration({GL_FASTEST, GL_NICEST, GL_DONT_CARE}));
     }},
    {"glPixelMapuiv",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum map = in.enumeration(kPixelMaps);
       const GLsizei size = in.bounded_size(256);
       glPixelMapuiv(map, size, static_cast<const GLuint*>(memory.image_source(size_t(std::max(size, 0)) * 4, size < 0)));
     }},
    {"glMap1d", map1d},
    {"glMap2d", map2d},
    {"glEvalMesh1",
     [](FuzzInput& in, ClientMemory&) {
       const GLenum mode = in.enumeration({GL_POINT, GL_LINE});
       const GLint first = in.integer(-2, 16);
       glEvalMesh1(mode, first, GLint(std::min<int64_t>(in.integer(-2, 16), int64_t(first) + 64)));
     }},
    {"glMultiDrawElements", [](FuzzInput& in, ClientMemory&) { multi_draw_elements(in, glMultiDrawElements); }},
    {"glMultiDrawElementsEXT", [](FuzzInput& in, ClientMemory&) { multi_draw_elements(in, glMultiDrawElementsEXT); }},
};

}  // namespace

std::span<const GlCall> parameter_calls() { return kCalls; }

}  // namespace pineda::fuzz
