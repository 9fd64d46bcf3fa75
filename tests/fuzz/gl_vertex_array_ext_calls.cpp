// The fuzzed EXT_vertex_array pointer calls (and EXT_fog_coord's, EXT_secondary_color's): the
// GL 1.1 pointer calls with a count of vertices that GL ignores, so the pointer still covers
// vertices 0 to kMaxVertexIndex whatever the count says.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "tests/fuzz/client_arrays.h"
#include "tests/fuzz/gl_calls.h"

namespace pineda::fuzz {
namespace {

constexpr GLenum kArrayTypes[] = {GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT,
                                  GL_INT,  GL_UNSIGNED_INT,  GL_FLOAT, GL_DOUBLE};

GLsizei vertex_count(FuzzInput& in) { return in.bounded_size(8); }

const GlCall kCalls[] = {
    {"glVertexPointerEXT",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLint size = in.integer(2, 4);
       const GLenum type = in.enumeration(kArrayTypes);
       const GLsizei stride = array_stride(in);
       glVertexPointerEXT(size, type, stride, vertex_count(in), array_pointer(in, memory));
     }},
    {"glColorPointerEXT",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLint size = in.integer(3, 4);
       const GLenum type = in.enumeration(kArrayTypes);
       const GLsizei stride = array_stride(in);
       glColorPointerEXT(size, type, stride, vertex_count(in), array_pointer(in, memory));
     }},
    {"glTexCoordPointerEXT",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLint size = in.integer(1, 4);
       const GLenum type = in.enumeration(kArrayTypes);
       const GLsizei stride = array_stride(in);
       glTexCoordPointerEXT(size, type, stride, vertex_count(in), array_pointer(in, memory));
     }},
    {"glNormalPointerEXT",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum type = in.enumeration(kArrayTypes);
       const GLsizei stride = array_stride(in);
       glNormalPointerEXT(type, stride, vertex_count(in), array_pointer(in, memory));
     }},
    {"glIndexPointerEXT",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum type = in.enumeration(kArrayTypes);
       const GLsizei stride = array_stride(in);
       glIndexPointerEXT(type, stride, vertex_count(in), array_pointer(in, memory));
     }},
    {"glEdgeFlagPointerEXT",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLsizei stride = array_stride(in);
       glEdgeFlagPointerEXT(stride, vertex_count(in), static_cast<const GLboolean*>(array_pointer(in, memory)));
     }},
    {"glFogCoordPointerEXT",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum type = in.enumeration({GL_FLOAT, GL_DOUBLE});
       glFogCoordPointerEXT(type, array_stride(in), array_pointer(in, memory));
     }},
    {"glSecondaryColorPointerEXT",
     [](FuzzInput& in, ClientMemory& memory) {
       const GLenum type = in.enumeration(kArrayTypes);
       glSecondaryColorPointerEXT(3, type, array_stride(in), array_pointer(in, memory));
     }},
};

}  // namespace

std::span<const GlCall> vertex_array_ext_calls() { return kCalls; }

}  // namespace pineda::fuzz
