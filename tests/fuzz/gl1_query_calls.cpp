// The fuzzed integer queries of GL 1.x float state (lights, materials, texture coordinate
// generation): the state is set from floats that may be NaN, infinite or 1e30.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <vector>

#include "tests/fuzz/gl_calls.h"

namespace pineda::fuzz {
namespace {

const GlCall kCalls[] = {
    {"glGetLightiv",
     [](FuzzInput& in, ClientMemory&) {
       std::vector<GLint> out(4);
       const GLenum light = in.enumeration({GL_LIGHT0, GL_LIGHT1, GL_LIGHT7});
       glGetLightiv(light,
                    in.enumeration({GL_AMBIENT, GL_DIFFUSE, GL_POSITION, GL_SPOT_DIRECTION, GL_SPOT_EXPONENT,
                                    GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION, GL_QUADRATIC_ATTENUATION}),
                    out.data());
     }},
    {"glGetMaterialiv",
     [](FuzzInput& in, ClientMemory&) {
       std::vector<GLint> out(4);
       const GLenum face = in.enumeration({GL_FRONT, GL_BACK});
       glGetMaterialiv(face,
                       in.enumeration({GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS,
                                       GL_COLOR_INDEXES}),
                       out.data());
     }},
    {"glGetTexGeniv",
     [](FuzzInput& in, ClientMemory&) {
       std::vector<GLint> out(4);
       const GLenum coord = in.enumeration({GL_S, GL_T, GL_R, GL_Q});
       glGetTexGeniv(coord, in.enumeration({GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE}), out.data());
     }},
};

}  // namespace

std::span<const GlCall> query_calls() { return kCalls; }

}  // namespace pineda::fuzz
