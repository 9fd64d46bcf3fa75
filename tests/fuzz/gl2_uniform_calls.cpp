// The fuzzed GL 2.x uniform and generic vertex attribute calls, and their ARB names. Locations are the current
// program's (looked up by name), small numbers (some stale after a relink), -1 or extremes;
// counts run past every array and go negative; values come from ClientMemory, which holds
// kMaxUniformCount of the largest (mat4) uniform.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <vector>

#include "tests/fuzz/client_arrays.h"
#include "tests/fuzz/gl_calls.h"

namespace pineda::fuzz {
namespace {

constexpr GLsizei kMaxUniformCount = GLsizei(64 * 1024 / (16 * sizeof(GLfloat)));
static_assert(kMaxUniformCount * 16 * sizeof(GLfloat) <= 64 * 1024, "ClientMemory::arrays holds the values");

constexpr const char* kLocationNames[] = {"u_mvp",     "u_offsets", "u_offsets[1]", "u_normal", "u_skew",
                                          "u_weights", "u_weights[3]", "u_texture", "u_tint",  "u_mode",
                                          "u_flag",    "u_colors",  "u_colors[1]", "u_wide",   "u_cube"};

GLint location(FuzzInput& in) {
  const uint8_t pick = in.byte();
  if (pick % 2 == 0) return in.integer(-1, 24);
  GLint program = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  return glGetUniformLocation(GLuint(program), kLocationNames[(pick / 2) % std::size(kLocationNames)]);
}

GLsizei uniform_count(FuzzInput& in) { return std::min(in.integer(-1, 6), kMaxUniformCount); }

template <typename T>
const T* values(const ClientMemory& memory) {
  return reinterpret_cast<const T*>(memory.arrays.data());
}

template <typename T>
void uniform_vector(FuzzInput& in, const ClientMemory& memory, void (*set)(GLint, GLsizei, const T*)) {
  const GLint at = location(in);
  set(at, uniform_count(in), values<T>(memory));
}

void uniform_matrix(FuzzInput& in, const ClientMemory& memory,
                    void (*set)(GLint, GLsizei, GLboolean, const GLfloat*)) {
  const GLint at = location(in);
  const GLsizei count = uniform_count(in);
  set(at, count, in.boolean(), values<GLfloat>(memory));
}

GLuint attrib_index(FuzzInput& in) { return GLuint(in.integer(0, 17)); }

template <typename T>
void get_vertex_attrib(FuzzInput& in, void (*get)(GLuint, GLenum, T*)) {
  std::vector<T> out(4);  // GL_CURRENT_VERTEX_ATTRIB, the largest
  const GLuint index = attrib_index(in);
  get(index,
      in.enumeration({GL_CURRENT_VERTEX_ATTRIB, GL_VERTEX_ATTRIB_ARRAY_ENABLED, GL_VERTEX_ATTRIB_ARRAY_SIZE,
                      GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, GL_VERTEX_ATTRIB_ARRAY_STRIDE, GL_VERTEX_ATTRIB_ARRAY_TYPE,
                      GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING}),
      out.data());
}

template <typename T>
void get_uniform(FuzzInput& in, void (*get)(GLuint, GLint, T*)) {
  std::vector<T> out(16);  // a mat4, the largest uniform
  const GLuint program = in.name();
  get(program, location(in), out.data());
}

void vertex_attrib_pointer(FuzzInput& in, ClientMemory& memory,
                           void (*set)(GLuint, GLint, GLenum, GLboolean, GLsizei, const void*)) {
  const GLuint index = attrib_index(in);
  const GLint size = in.integer(1, 4);
  const GLenum type = in.enumeration({GL_BYTE, GL_UNSIGNED_BYTE, GL_SHORT, GL_UNSIGNED_SHORT, GL_INT,
                                      GL_UNSIGNED_INT, GL_FLOAT, GL_DOUBLE});
  const GLboolean normalized = in.boolean();
  const GLsizei stride = array_stride(in);
  set(index, size, type, normalized, stride, array_pointer(in, memory));
}

void get_vertex_attrib_pointer(FuzzInput& in, void (*get)(GLuint, GLenum, void**)) {
  void* pointer = nullptr;
  get(attrib_index(in), in.enumeration({GL_VERTEX_ATTRIB_ARRAY_POINTER}), &pointer);
}

const GlCall kCalls[] = {
    {"glUniform1f", [](FuzzInput& in, ClientMemory&) { glUniform1f(location(in), in.real()); }},
    {"glUniform2f", [](FuzzInput& in, ClientMemory&) { glUniform2f(location(in), in.real(), in.real()); }},
    {"glUniform3f", [](FuzzInput& in, ClientMemory&) { glUniform3f(location(in), in.real(), in.real(), in.real()); }},
    {"glUniform4f",
     [](FuzzInput& in, ClientMemory&) { glUniform4f(location(in), in.real(), in.real(), in.real(), in.real()); }},
    {"glUniform1i", [](FuzzInput& in, ClientMemory&) { glUniform1i(location(in), in.integer(-1, 40)); }},
    {"glUniform2i", [](FuzzInput& in, ClientMemory&) { glUniform2i(location(in), in.integer(-1, 4), in.integer(-1, 4)); }},
    {"glUniform3i",
     [](FuzzInput& in, ClientMemory&) { glUniform3i(location(in), in.integer(-1, 4), in.integer(-1, 4), in.integer(-1, 4)); }},
    {"glUniform4i",
     [](FuzzInput& in, ClientMemory&) {
       glUniform4i(location(in), in.integer(-1, 4), in.integer(-1, 4), in.integer(-1, 4), in.integer(-1, 4));
     }},
    {"glUniform1fv", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform1fv); }},
    {"glUniform2fv", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform2fv); }},
    {"glUniform3fv", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform3fv); }},
    {"glUniform4fv", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform4fv); }},
    {"glUniform1iv", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform1iv); }},
    {"glUniform2iv", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform2iv); }},
    {"glUniform3iv", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform3iv); }},
    {"glUniform4iv", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform4iv); }},
    {"glUniformMatrix2fv", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix2fv); }},
    {"glUniformMatrix3fv", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix3fv); }},
    {"glUniformMatrix4fv", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix4fv); }},
    {"glUniformMatrix2x3fv", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix2x3fv); }},
    {"glUniformMatrix3x2fv", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix3x2fv); }},
    {"glUniformMatrix2x4fv", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix2x4fv); }},
    {"glUniformMatrix4x2fv", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix4x2fv); }},
    {"glUniformMatrix3x4fv", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix3x4fv); }},
    {"glUniformMatrix4x3fv", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix4x3fv); }},
    {"glGetUniformfv", [](FuzzInput& in, ClientMemory&) { get_uniform(in, glGetUniformfv); }},
    {"glGetUniformiv", [](FuzzInput& in, ClientMemory&) { get_uniform(in, glGetUniformiv); }},
    {"glVertexAttrib1f", [](FuzzInput& in, ClientMemory&) { glVertexAttrib1f(attrib_index(in), in.real()); }},
    {"glVertexAttrib4f",
     [](FuzzInput& in, ClientMemory&) {
       glVertexAttrib4f(attrib_index(in), in.real() * 8, in.real() * 8, in.real(), in.real());
     }},
    {"glVertexAttrib4fv",
     [](FuzzInput& in, ClientMemory& memory) {
       glVertexAttrib4fv(attrib_index(in), values<GLfloat>(memory) + in.offset(64));
     }},
    {"glVertexAttribPointer",
     [](FuzzInput& in, ClientMemory& memory) { vertex_attrib_pointer(in, memory, glVertexAttribPointer); }},
    {"glEnableVertexAttribArray", [](FuzzInput& in, ClientMemory&) { glEnableVertexAttribArray(attrib_index(in)); }},
    {"glDisableVertexAttribArray", [](FuzzInput& in, ClientMemory&) { glDisableVertexAttribArray(attrib_index(in)); }},
    {"glGetVertexAttribfv", [](FuzzInput& in, ClientMemory&) { get_vertex_attrib(in, glGetVertexAttribfv); }},
    {"glGetVertexAttribiv", [](FuzzInput& in, ClientMemory&) { get_vertex_attrib(in, glGetVertexAttribiv); }},
    {"glGetVertexAttribPointerv",
     [](FuzzInput& in, ClientMemory&) { get_vertex_attrib_pointer(in, glGetVertexAttribPointerv); }},
    // The ARB_shader_objects and ARB_vertex_shader names of the same calls.
    {"glUniform1fvARB", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform1fvARB); }},
    {"glUniform2fvARB", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform2fvARB); }},
    {"glUniform3fvARB", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform3fvARB); }},
    {"glUniform4fvARB", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform4fvARB); }},
    {"glUniform1ivARB", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform1ivARB); }},
    {"glUniform2ivARB", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform2ivARB); }},
    {"glUniform3ivARB", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform3ivARB); }},
    {"glUniform4ivARB", [](FuzzInput& in, ClientMemory& memory) { uniform_vector(in, memory, glUniform4ivARB); }},
    {"glUniformMatrix2fvARB", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix2fvARB); }},
    {"glUniformMatrix3fvARB", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix3fvARB); }},
    {"glUniformMatrix4fvARB", [](FuzzInput& in, ClientMemory& memory) { uniform_matrix(in, memory, glUniformMatrix4fvARB); }},
    {"glGetUniformfvARB", [](FuzzInput& in, ClientMemory&) { get_uniform(in, glGetUniformfvARB); }},
    {"glGetUniformivARB", [](FuzzInput& in, ClientMemory&) { get_uniform(in, glGetUniformivARB); }},
    {"glGetVertexAttribdv", [](FuzzInput& in, ClientMemory&) { get_vertex_attrib(in, glGetVertexAttribdv); }},
    {"glGetVertexAttribdvARB", [](FuzzInput& in, ClientMemory&) { get_vertex_attrib(in, glGetVertexAttribdvARB); }},
    {"glGetVertexAttribfvARB", [](FuzzInput& in, ClientMemory&) { get_vertex_attrib(in, glGetVertexAttribfvARB); }},
    {"glGetVertexAttribivARB", [](FuzzInput& in, ClientMemory&) { get_vertex_attrib(in, glGetVertexAttribivARB); }},
    {"glVertexAttribPointerARB", [](FuzzInput& in, ClientMemory& memory) { vertex_attrib_pointer(in, memory, glVertexAttribPointerARB); }},
    {"glGetVertexAttribPointervARB", [](FuzzInput& in, ClientMemory&) { get_vertex_attrib_pointer(in, glGetVertexAttribPointervARB); }},
};

}  // namespace

std::span<const GlCall> uniform_calls() { return kCalls; }

}  // namespace pineda::fuzz
