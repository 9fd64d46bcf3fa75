#define GL_GLEXT_PROTOTYPES
#include "tests/fuzz/client_arrays.h"

#include <GL/glext.h>

namespace pineda::fuzz {
namespace {

bool buffer_bound() {
  GLint bound = 0;
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &bound);
  return bound != 0;
}

bool texture_coord_array_uses_buffer(GLuint name) {
  GLint units = 0, active = 0, bound = 0;
  glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
  glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &active);
  bool used = false;
  for (GLint u = 0; u < units && !used; ++u) {
    glClientActiveTexture(GL_TEXTURE0 + u);
    glGetIntegerv(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, &bound);
    used = GLuint(bound) == name;
  }
  glClientActiveTexture(GLenum(active));
  return used;
}

bool attrib_array_uses_buffer(GLuint name) {
  GLint attribs = 0;
  glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &attribs);
  for (GLint i = 0; i < attribs; ++i) {
    GLint bound = 0;
    glGetVertexAttribiv(GLuint(i), GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &bound);
    if (GLuint(bound) == name) return true;
  }
  return false;
}

}  // namespace

const void* array_pointer(FuzzInput& in, const ClientMemory& memory) {
  if (buffer_bound()) return reinterpret_cast<const void*>(uintptr_t(in.integer(0, 4096)));
  return memory.arrays.data() + in.offset(kArrayOffsetMax);
}

GLsizei array_stride(FuzzInput& in) {
  const GLsizei s = in.bounded_size(kArrayStrideMax / 4);
  return s < 0 ? -4 : 4 * s;
}

bool array_uses_buffer(GLuint name) {
  constexpr GLenum kBindings[] = {GL_VERTEX_ARRAY_BUFFER_BINDING,    GL_COLOR_ARRAY_BUFFER_BINDING,
                                  GL_NORMAL_ARRAY_BUFFER_BINDING,    GL_INDEX_ARRAY_BUFFER_BINDING,
                                  GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, GL_FOG_COORD_ARRAY_BUFFER_BINDING,
                                  GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING};
  GLint bound = 0;
  for (GLenum binding : kBindings) {
    glGetIntegerv(binding, &bound);
    if (GLuint(bound) == name) return true;
  }
  return texture_coord_array_uses_buffer(name) || attrib_array_uses_buffer(name);
}

}  // namespace pineda::fuzz
