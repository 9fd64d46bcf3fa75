// The fuzzed OpenGL ES 1.1 entry points: the fixed-point (*x, *xOES) and single-precision
// (glOrthof ...) calls, OES_draw_texture, OES_point_size_array and the OES names of the
// blend and buffer calls. A desktop context rejects them with GL_INVALID_OPERATION; they do
// their work once an egl_calls.cpp entry makes an OpenGL ES 1.1 context current.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <vector>

#include "tests/fuzz/client_arrays.h"
#include "tests/fuzz/es_prototypes.h"
#include "tests/fuzz/gl_enum_lists.h"
#include "tests/fuzz/sized_query.h"
#include "tests/fuzz/typed_call.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kBlendEquations[] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT, GL_MIN, GL_MAX};
constexpr GLenum kBlendFactors[] = {GL_ZERO, GL_ONE, GL_SRC_COLOR, GL_ONE_MINUS_DST_COLOR, GL_SRC_ALPHA,
                                    GL_ONE_MINUS_SRC_ALPHA, GL_DST_ALPHA, GL_SRC_ALPHA_SATURATE};
constexpr GLenum kBufferTargets[] = {GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER};

void* map_buffer(FuzzInput& in, void* (*map)(GLenum, GLenum)) {
  const GLenum target = in.enumeration(kBufferTargets);
  return map(target, in.enumeration({GL_WRITE_ONLY, GL_READ_ONLY}));
}

const GlCall kCalls[] = {
    PINEDA_TYPED_CALL(glClearColorx),
    PINEDA_TYPED_CALL(glClearColorxOES),
    PINEDA_TYPED_CALL(glClearDepthf),
    PINEDA_TYPED_CALL(glClearDepthfOES),
    PINEDA_TYPED_CALL(glClearDepthx),
    PINEDA_TYPED_CALL(glClearDepthxOES),
    PINEDA_TYPED_CALL(glClearIndex),
    PINEDA_TYPED_CALL(glColor4x),
    PINEDA_TYPED_CALL(glColor4xOES),
    PINEDA_TYPED_CALL(glDepthRangef),
    PINEDA_TYPED_CALL(glDepthRangefOES),
    PINEDA_TYPED_CALL(glDepthRangex),
    PINEDA_TYPED_CALL(glDepthRangexOES),
    PINEDA_TYPED_CALL(glDrawTexfOES),
    PINEDA_TYPED_CALL(glDrawTexfvOES),
    PINEDA_TYPED_CALL(glDrawTexiOES),
    PINEDA_TYPED_CALL(glDrawTexivOES),
    PINEDA_TYPED_CALL(glDrawTexsOES),
    PINEDA_TYPED_CALL(glDrawTexsvOES),
    PINEDA_TYPED_CALL(glDrawTexxOES),
    PINEDA_TYPED_CALL(glDrawTexxvOES),
    PINEDA_TYPED_CALL(glFrustumf),
    PINEDA_TYPED_CALL(glFrustumfOES),
    PINEDA_TYPED_CALL(glFrustumx),
    PINEDA_TYPED_CALL(glFrustumxOES),
    PINEDA_TYPED_CALL(glLineWidthx),
    PINEDA_TYPED_CALL(glLineWidthxOES),
    PINEDA_TYPED_CALL(glLoadMatrixx),
    PINEDA_TYPED_CALL(glLoadMatrixxOES),
    PINEDA_TYPED_CALL(glMultMatrixx),
    PINEDA_TYPED_CALL(glMultMatrixxOES),
    PINEDA_TYPED_CALL(glNormal3x),
    PINEDA_TYPED_CALL(glNormal3xOES),
    PINEDA_TYPED_CALL(glOrthof),
    PINEDA_TYPED_CALL(glOrthofOES),
    PINEDA_TYPED_CALL(glOrthox),
    PINEDA_TYPED_CALL(glOrthoxOES),
    PINEDA_TYPED_CALL(glPointSizex),
    PINEDA_TYPED_CALL(glPointSizexOES),
    PINEDA_TYPED_CALL(glPolygonOffsetx),
    PINEDA_TYPED_CALL(glPolygonOffsetxOES),
    PINEDA_TYPED_CALL(glRotatex),
    PINEDA_TYPED_CALL(glRotatexOES),
    PINEDA_TYPED_CALL(glScalex),
    PINEDA_TYPED_CALL(glScalexOES),
    PINEDA_TYPED_CALL(glTranslatex),
    PINEDA_TYPED_CALL(glTranslatexOES),
    PINEDA_TYPED_CALL_AFTER(glAlphaFuncx, kCompareFunctions),
    PINEDA_TYPED_CALL_AFTER(glAlphaFuncxOES, kCompareFunctions),
    PINEDA_TYPED_CALL_AFTER(glClipPlanef, kClipPlanes),
    PINEDA_TYPED_CALL_AFTER(glClipPlanefOES, kClipPlanes),
    PINEDA_TYPED_CALL_AFTER(glClipPlanex, kClipPlanes),
    PINEDA_TYPED_CALL_AFTER(glClipPlanexOES, kClipPlanes),
    PINEDA_TYPED_CALL_AFTER(glFogx, kFogNames),
    PINEDA_TYPED_CALL_AFTER(glFogxOES, kFogNames),
    PINEDA_TYPED_CALL_AFTER(glFogxvOES, kFogNames),
    PINEDA_TYPED_CALL_AFTER(glLightModelx, kLightModelNames),
    PINEDA_TYPED_CALL_AFTER(glLightModelxOES, kLightModelNames),
    PINEDA_TYPED_CALL_AFTER(glLightModelxvOES, kLightModelNames),
    PINEDA_TYPED_CALL_AFTER(glMultiTexCoord4x, kTextureUnits),
    PINEDA_TYPED_CALL_AFTER(glMultiTexCoord4xOES, kTextureUnits),
    PINEDA_TYPED_CALL_AFTER(glPointParameterx, kPointParameterNames),
    PINEDA_TYPED_CALL_AFTER(glPointParameterxOES, kPointParameterNames),
    PINEDA_TYPED_CALL_AFTER(glPointParameterxvOES, kPointParameterNames),
    PINEDA_TYPED_CALL_AFTER(glFogxv, kFogNames),
    PINEDA_TYPED_CALL_AFTER(glLightModelxv, kLightModelNames),
    PINEDA_TYPED_CALL_AFTER(glPointParameterxv, kPointParameterNames),
    PINEDA_TYPED_CALL_AFTER2(glLightx, kLights, kLightNames),
    PINEDA_TYPED_CALL_AFTER2(glLightxOES, kLights, kLightNames),
    PINEDA_TYPED_CALL_AFTER2(glLightxv, kLights, kLightNames),
    PINEDA_TYPED_CALL_AFTER2(glLightxvOES, kLights, kLightNames),
    PINEDA_TYPED_CALL_AFTER2(glMaterialx, kMaterialFaces, kMaterialNames),
    PINEDA_TYPED_CALL_AFTER2(glMaterialxOES, kMaterialFaces, kMaterialNames),
    PINEDA_TYPED_CALL_AFTER2(glMaterialxv, kMaterialFaces, kMaterialNames),
    PINEDA_TYPED_CALL_AFTER2(glMaterialxvOES, kMaterialFaces, kMaterialNames),
    PINEDA_TYPED_CALL_AFTER2(glTexEnvx, kTexEnvTargets, kTexEnvNames),
    PINEDA_TYPED_CALL_AFTER2(glTexEnvxOES, kTexEnvTargets, kTexEnvNames),
    PINEDA_TYPED_CALL_AFTER2(glTexEnvxv, kTexEnvTargets, kTexEnvNames),
    PINEDA_TYPED_CALL_AFTER2(glTexEnvxvOES, kTexEnvTargets, kTexEnvNames),
    PINEDA_TYPED_CALL_AFTER2(glTexParameterx, kTextureTargets, kTexParameterNames),
    PINEDA_TYPED_CALL_AFTER2(glTexParameterxOES, kTextureTargets, kTexParameterNames),
    PINEDA_TYPED_CALL_AFTER2(glTexParameterxv, kTextureTargets, kTexParameterNames),
    PINEDA_TYPED_CALL_AFTER2(glTexParameterxvOES, kTextureTargets, kTexParameterNames),
    PINEDA_TYPED_CALL(glSampleCoveragex),
    PINEDA_TYPED_CALL(glSampleCoveragexOES),
    {"glGetFixedv", [](FuzzInput& in, ClientMemory&) { get_state(in, glGetFixedv); }},
    {"glGetFixedvOES", [](FuzzInput& in, ClientMemory&) { get_state(in, glGetFixedvOES); }},
    {"glGetClipPlanef", [](FuzzInput& in, ClientMemory&) { get_clip_plane(in, glGetClipPlanef); }},
    {"glGetClipPlanefOES", [](FuzzInput& in, ClientMemory&) { get_clip_plane(in, glGetClipPlanefOES); }},
    {"glGetClipPlanex", [](FuzzInput& in, ClientMemory&) { get_clip_plane(in, glGetClipPlanex); }},
    {"glGetClipPlanexOES", [](FuzzInput& in, ClientMemory&) { get_clip_plane(in, glGetClipPlanexOES); }},
    {"glGetLightxv", [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetLightxv, kLights, kLightQueries); }},
    {"glGetLightxvOES", [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetLightxvOES, kLights, kLightQueries); }},
    {"glGetMaterialxv",
     [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetMaterialxv, kMaterialFaces, kMaterialQueries); }},
    {"glGetMaterialxvOES",
     [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetMaterialxvOES, kMaterialFaces, kMaterialQueries); }},
    {"glGetTexEnvxv", [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetTexEnvxv, kTexEnvTargets, kTexEnvQueries); }},
    {"glGetTexEnvxvOES",
     [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetTexEnvxvOES, kTexEnvTargets, kTexEnvQueries); }},
    {"glGetTexParameterxv",
     [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetTexParameterxv, kTextureTargets, kTexParameterQueries); }},
    {"glGetTexParameterxvOES",
     [](FuzzInput& in, ClientMemory&) { sized_get(in, glGetTexParameterxvOES, kTextureTargets, kTexParameterQueries); }},
    {"glPointSizePointerOES",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum type = in.enumeration({GL_FLOAT, GL_FIXED, GL_SHORT});
       glPointSizePointerOES(type, array_stride(in), array_pointer(in, memory));
     }},
    {"glBlendEquationOES", [](FuzzInput& in, ClientMemory&) { glBlendEquationOES(in.enumeration(kBlendEquations)); }},
    {"glBlendEquationSeparateOES",
     [](FuzzInput& in, ClientMemory&) {
       glBlendEquationSeparateOES(in.enumeration(kBlendEquations), in.enumeration(kBlendEquations));
     }},
    {"glBlendFuncSeparateOES",
     [](FuzzInput& in, ClientMemory&) {
       glBlendFuncSeparateOES(in.enumeration(kBlendFactors), in.enumeration(kBlendFactors),
                              in.enumeration(kBlendFactors), in.enumeration(kBlendFactors));
     }},
    {"glMapBufferOES", [](FuzzInput& in, ClientMemory&) { map_buffer(in, glMapBufferOES); }},
    {"glUnmapBufferOES", [](FuzzInput& in, ClientMemory&) { glUnmapBufferOES(in.enumeration(kBufferTargets)); }},
    {"glGetBufferPointervOES",
     [](FuzzInput& in, ClientMemory&) {
       void* pointer = nullptr;
       glGetBufferPointervOES(in.enumeration(kBufferTargets), in.enumeration({GL_BUFFER_MAP_POINTER}), &pointer);
     }},
};

}  // namespace

std::span<const GlCall> es1_calls() { return kCalls; }

}  // namespace pineda::fuzz
