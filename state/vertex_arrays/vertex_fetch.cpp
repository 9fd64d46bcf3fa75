#include "state/vertex_arrays/vertex_fetch.h"

#include <algorithm>
#include <cstring>

#include "state/context.h"
#include "state/programs/generic_attribs.h"
#include "state/programs/program_objects.h"
#include "state/unaligned.h"
#include "state/vertex_arrays/vertex_fetch_plan.h"

namespace pineda {

float read_vertex_component(const uint8_t* p, unsigned type, bool normalize) {
  switch (type) {
    case GL_BYTE: { auto v = load_unaligned<GLbyte>(p); return normalize ? (2.f * v + 1.f) / 255.f : v; }
    case GL_UNSIGNED_BYTE: { auto v = load_unaligned<GLubyte>(p); return normalize ? v / 255.f : v; }
    case GL_SHORT: { auto v = load_unaligned<GLshort>(p); return normalize ? (2.f * v + 1.f) / 65535.f : v; }
    case GL_UNSIGNED_SHORT: { auto v = load_unaligned<GLushort>(p); return normalize ? v / 65535.f : v; }
    case GL_INT: { auto v = load_unaligned<GLint>(p); return normalize ? float((2.0 * v + 1.0) / 4294967295.0) : float(v); }
    case GL_UNSIGNED_INT: { auto v = load_unaligned<GLuint>(p); return normalize ? float(v / 4294967295.0) : float(v); }
    case GL_FLOAT: return load_unaligned<GLfloat>(p);
    case GL_DOUBLE: return static_cast<float>(load_unaligned<GLdouble>(p));
    case GL_FIXED: return static_cast<float>(load_unaligned<GLfixed>(p)) / 65536.f;  // OpenGL ES 1.1
    default: return 0.f;
  }
}

namespace {

// Reads `array.size` components of element `index` into dst (which keeps its defaults
// for the components the array does not have, and all of them when the element lies
// outside the array's buffer object).
void read_array(const ClientArray& array, size_t index, float* dst, bool normalize) {
  const uint8_t* p = array_element(array, index, size_t(gl_type_size(array.type)) * array.size);
  if (p) read_components(p, array.type, array.size, normalize, dst);
}

}  // namespace

const uint8_t* array_element(const ClientArray& array, size_t index, size_t bytes) {
  const size_t stride = array.stride ? size_t(array.stride) : bytes;
  if (!array.buffer) return static_cast<const uint8_t*>(array.pointer) + stride * index;
  if (stride && index > (SIZE_MAX - reinterpret_cast<uintptr_t>(array.pointer)) / stride) return nullptr;
  return buffer_range(*array.buffer, reinterpret_cast<uintptr_t>(array.pointer) + stride * index, bytes);
}

int gl_type_size(unsigned type) {
  switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_INT: case GL_UNSIGNED_INT: case GL_FLOAT: case GL_FIXED: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
  }
}

float fetch_index(const Context& ctx, size_t index) {
  float value = ctx.color_index.current_index;
  if (ctx.index_array.active()) read_array(ctx.index_array, index, &value, false);
  return value;
}

void take_current_index(Context& ctx, size_t index) {
  if (ctx.index_array.active()) ctx.color_index.current_index = fetch_index(ctx, index);
}

// The position, which is also generic attribute 0 (fetch_generic reads it here).
void fetch_array_position(const Context& ctx, size_t index, float position[4]) {
  if (read_generic_position(ctx, index, position)) return;
  if (ctx.vertex_array.active())
    read_array(ctx.vertex_array, index, position, false);
  else if (ctx.es2())  // ES 2.0: attribute 0 has a current value like the others
    std::copy(ctx.programs.current_attrib[0].begin(), ctx.programs.current_attrib[0].end(), position);
}

bool array_edge_flag(const Context& ctx, size_t index) {
  if (!ctx.edge_flag_array.active()) return ctx.current_edge_flag;
  const uint8_t* p = array_element(ctx.edge_flag_array, index, sizeof(GLboolean));
  return p ? *p != GL_FALSE : ctx.current_edge_flag;
}

void fetch_vertex(const Context& ctx, size_t index, raster::VertexInput& out) {
  VertexFetchPlan plan;
  plan.build(ctx);
  plan.fetch(index, out);
}

void fetch_vertex_source(const Context& ctx, size_t index, raster::VertexInput& out) {
  out = raster::VertexInput{};
  out.source = static_cast<uint32_t>(std::min<size_t>(index, UINT32_MAX - 1));
  fetch_array_position(ctx, index, out.position);
  out.edge_flag = array_edge_flag(ctx, index);
}

bool vertex_shader_reads_generic_attributes_only(const Context& ctx) {
  const LinkedProgram* exec = ctx.programs.active();
  return exec && exec->program && exec->vertex_shader && exec->generic_attributes_only;
}

}  // namespace pineda
