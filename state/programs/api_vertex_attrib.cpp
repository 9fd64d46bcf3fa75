// Generic vertex attributes (GL 2.0 2.7, 2.8, 6.1.14): current values, arrays, queries.
// Attribute 0 is the vertex position: glVertexAttrib*(0, ...) acts as glVertex.
#include <algorithm>

#include "glapi/gl_entry_points.h"
#include "state/component_convert.h"
#include "state/context.h"
#include "state/pixels/pixel_state.h"

namespace pineda::gl {
namespace {

bool valid_index(Context& ctx, GLuint index) {
  if (index < static_cast<GLuint>(kMaxVertexAttribs)) return true;
  ctx.record_error(GL_INVALID_VALUE, "index is not less than GL_MAX_VERTEX_ATTRIBS");
  return false;
}

void set_attrib(Context& ctx, GLuint index, float x, float y, float z, float w) {
  if (!valid_index(ctx, index)) return;
  if (index == 0 && !ctx.es2()) return Vertex4f(ctx, x, y, z, w);  // ES 2.0: not the position
  ctx.programs.current_attrib[index] = {x, y, z, w};
}

template <typename T>
void set_attrib_v(Context& ctx, GLuint index, int n, const T* v, bool normalize) {
  if (!valid_index(ctx, index) || !v) return;
  float c[4] = {0.f, 0.f, 0.f, 1.f};
  for (int i = 0; i < n; ++i) c[i] = normalize ? norm(v[i]) : static_cast<float>(v[i]);
  set_attrib(ctx, index, c[0], c[1], c[2], c[3]);
}

}  // namespace

#define PINEDA_ATTRIB(T, suffix)                                                                        \
  void VertexAttrib1##suffix(Context& ctx, GLuint index, T x) { set_attrib(ctx, index, x, 0.f, 0.f, 1.f); } \
  void VertexAttrib2##suffix(Context& ctx, GLuint index, T x, T y) { set_attrib(ctx, index, x, y, 0.f, 1.f); } \
  void VertexAttrib3##suffix(Context& ctx, GLuint index, T x, T y, T z) {                                 \
    set_attrib(ctx, index, x, y, z, 1.f);                                                               \
  }                                                                                                     \
  void VertexAttrib4##suffix(Context& ctx, GLuint index, T x, T y, T z, T w) {                           \
    set_attrib(ctx, index, x, y, z, w);                                                                 \
  }                                                                                                     \
  void VertexAttrib1##suffix##v(Context& ctx, GLuint index, const T* v) { set_attrib_v(ctx, index, 1, v, false); } \
  void VertexAttrib2##suffix##v(Context& ctx, GLuint index, const T* v) { set_attrib_v(ctx, index, 2, v, false); } \
  void VertexAttrib3##suffix##v(Context& ctx, GLuint index, const T* v) { set_attrib_v(ctx, index, 3, v, false); } \
  void VertexAttrib4##suffix##v(Context& ctx, GLuint index, const T* v) { set_attrib_v(ctx, index, 4, v, false); }
PINEDA_ATTRIB(GLshort, s)
PINEDA_ATTRIB(GLfloat, f)
PINEDA_ATTRIB(GLdouble, d)
#undef PINEDA_ATTRIB

#define PINEDA_ATTRIB4V(T, suffix)                                                                   \
  void VertexAttrib4##suffix##v(Context& ctx, GLuint index, const T* v) { set_attrib_v(ctx, index, 4, v, false); } \
  void VertexAttrib4N##suffix##v(Context& ctx, GLuint index, const T* v) { set_attrib_v(ctx, index, 4, v, true); }
PINEDA_ATTRIB4V(GLbyte, b)
PINEDA_ATTRIB4V(GLubyte, ub)
PINEDA_ATTRIB4V(GLint, i)
PINEDA_ATTRIB4V(GLuint, ui)
PINEDA_ATTRIB4V(GLushort, us)
#undef PINEDA_ATTRIB4V

void VertexAttrib4Nsv(Context& ctx, GLuint index, const GLshort* v) { set_attrib_v(ctx, index, 4, v, true); }

void VertexAttrib4Nub(Context& ctx, GLuint index, GLubyte x, GLubyte y, GLubyte z, GLubyte w) {
  set_attrib(ctx, index, norm(x), norm(y), norm(z), norm(w));
}

void VertexAttribPointer(Context& ctx, GLuint index, GLint size, GLenum type, GLboolean normalized, GLsizei stride,
                         const void* pointer) {
  if (!valid_index(ctx, index)) return;
  if (size < 1 || size > 4) return ctx.record_error(GL_INVALID_VALUE, "size is not 1, 2, 3 or 4");
  if (stride < 0) return ctx.record_error(GL_INVALID_VALUE, "stride is negative");
  switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: case GL_SHORT: case GL_UNSIGNED_SHORT: case GL_FLOAT: break;
    case GL_INT: case GL_UNSIGNED_INT: case GL_DOUBLE:
      if (ctx.es2()) return ctx.record_error(GL_INVALID_ENUM, "type is not a type of OpenGL ES 2.0");
      break;
    case GL_FIXED: break;  // OpenGL ES 2.0 2.8; desktop GL through GL_ARB_ES2_compatibility
    default: return ctx.record_error(GL_INVALID_ENUM, "type is not a vertex attribute type");
  }
  GenericArray& a = ctx.programs.arrays[index];
  a.size = size;
  a.type = type;
  a.normalized = normalized != GL_FALSE;
  a.stride = stride;
  a.pointer = pointer;
  a.buffer = ctx.buffers.array;
}

void EnableVertexAttribArray(Context& ctx, GLuint index) {
  if (valid_index(ctx, index)) ctx.programs.arrays[index].enabled = true;
}

void DisableVertexAttribArray(Context& ctx, GLuint index) {
  if (valid_index(ctx, index)) ctx.programs.arrays[index].enabled = false;
}

namespace {

// The values glGetVertexAttrib* returns; false after an error.
bool vertex_attrib_values(Context& ctx, GLuint index, GLenum pname, double out[4], int& n, bool& is_float) {
  if (!valid_index(ctx, index)) return false;
  const GenericArray& a = ctx.programs.arrays[index];
  n = 1;
  is_float = false;
  switch (pname) {
    case GL_VERTEX_ATTRIB_ARRAY_ENABLED: out[0] = a.enabled; return true;
    case GL_VERTEX_ATTRIB_ARRAY_SIZE: out[0] = a.size; return true;
    case GL_VERTEX_ATTRIB_ARRAY_STRIDE: out[0] = a.stride; return true;
    case GL_VERTEX_ATTRIB_ARRAY_TYPE: out[0] = a.type; return true;
    case GL_VERTEX_ATTRIB_ARRAY_NORMALIZED: out[0] = a.normalized; return true;
    case GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING: out[0] = buffer_name(a.buffer); return true;
    case GL_CURRENT_VERTEX_ATTRIB:
      if (index == 0 && !ctx.es2()) {
        ctx.record_error(GL_INVALID_OPERATION, "vertex attribute 0 has no current value outside OpenGL ES");
        return false;
      }
      n = 4;
      is_float = true;
      for (int i = 0; i < 4; ++i) out[i] = ctx.programs.current_attrib[index][i];
      return true;
    default: ctx.record_error(GL_INVALID_ENUM, "pname is not a vertex attribute parameter"); return false;
  }
}

}  // namespace

void GetVertexAttribfv(Context& ctx, GLuint index, GLenum pname, GLfloat* params) {
  double v[4];
  int n;
  bool is_float;
  if (!vertex_attrib_values(ctx, index, pname, v, n, is_float) || !params) return;
  for (int i = 0; i < n; ++i) params[i] = static_cast<GLfloat>(v[i]);
}

void GetVertexAttribdv(Context& ctx, GLuint index, GLenum pname, GLdouble* params) {
  double v[4];
  int n;
  bool is_float;
  if (!vertex_attrib_values(ctx, index, pname, v, n, is_float) || !params) return;
  for (int i = 0; i < n; ++i) params[i] = v[i];
}

void GetVertexAttribiv(Context& ctx, GLuint index, GLenum pname, GLint* params) {
  double v[4];
  int n;
  bool is_float;
  if (!vertex_attrib_values(ctx, index, pname, v, n, is_float) || !params) return;
  for (int i = 0; i < n; ++i)
    params[i] = is_float ? truncate_int_param(v[i]) : static_cast<GLint>(v[i]);
}

void GetVertexAttribPointerv(Context& ctx, GLuint index, GLenum pname, void** pointer) {
  if (!valid_index(ctx, index)) return;
  if (pname != GL_VERTEX_ATTRIB_ARRAY_POINTER)
    return ctx.record_error(GL_INVALID_ENUM, "pname is not GL_VERTEX_ATTRIB_ARRAY_POINTER");
  if (pointer) *pointer = const_cast<void*>(ctx.programs.arrays[index].pointer);
}

}  // namespace pineda::gl
