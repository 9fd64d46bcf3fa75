#include "state/programs/generic_attribs.h"

#include <algorithm>
#include <cstring>

#include "state/context.h"
#include "state/vertex_arrays/vertex_fetch.h"

namespace pineda {
namespace {

void read_generic_array(const GenericArray& a, size_t index, float out[4]) {
  const uint8_t* p = generic_element(a, index);
  if (!p) return;
  const int component = gl_type_size(a.type);
  out[0] = 0.f;
  out[1] = 0.f;
  out[2] = 0.f;
  out[3] = 1.f;
  for (int c = 0; c < a.size; ++c) out[c] = read_vertex_component(p + c * component, a.type, a.normalized);
}

}  // namespace

const uint8_t* generic_element(const GenericArray& a, size_t index) {
  const size_t bytes = size_t(gl_type_size(a.type)) * size_t(a.size);
  const size_t stride = a.stride ? size_t(a.stride) : bytes;
  if (!a.buffer) return static_cast<const uint8_t*>(a.pointer) + stride * index;
  if (stride && index > (SIZE_MAX - reinterpret_cast<uintptr_t>(a.pointer)) / stride) return nullptr;
  return buffer_range(*a.buffer, reinterpret_cast<uintptr_t>(a.pointer) + stride * index, bytes);
}

void fetch_generic_element(const Context& ctx, int index, size_t element, float out[4]) {
  if (index == 0) {
    const float position[4] = {0.f, 0.f, 0.f, 1.f};
    std::copy(position, position + 4, out);
    return fetch_array_position(ctx, element, out);
  }
  const ProgramState& ps = ctx.programs;
  std::copy(ps.current_attrib[index].begin(), ps.current_attrib[index].end(), out);
  if (ps.arrays[index].active()) read_generic_array(ps.arrays[index], element, out);
}

bool direct_array_view(const Context& ctx, AttribSource source, int index, DirectArrayView& out) {
  if (source != AttribSource::Arrays || index < 0 || index >= kMaxVertexAttribs) return false;
  const GenericArray& a = ctx.programs.arrays[index];
  out.unorm8 = a.type == GL_UNSIGNED_BYTE && a.normalized;
  if (!a.active() || (a.type != GL_FLOAT && !out.unorm8)) return false;
  const size_t bytes = size_t(gl_type_size(a.type)) * size_t(a.size);
  out.stride = a.stride ? size_t(a.stride) : bytes;
  out.size = a.size;
  // The position (array 0) of an element outside the buffer is a fetched vertex's default.
  static constexpr float kDefaultPosition[4] = {0.f, 0.f, 0.f, 1.f};
  out.current = index == 0 ? kDefaultPosition : ctx.programs.current_attrib[index].data();
  if (!a.buffer) {
    out.base = static_cast<const uint8_t*>(a.pointer);
    out.count = SIZE_MAX;
    return true;
  }
  const size_t total = a.buffer->data.size(), offset = reinterpret_cast<uintptr_t>(a.pointer);
  out.base = a.buffer->data.data() + std::min(offset, total);
  out.count = elements_inside(*a.buffer, offset, out.stride, bytes);
  return true;
}

bool read_generic_position(const Context& ctx, size_t index, float out[4]) {
  const GenericArray& a = ctx.programs.arrays[0];
  if (!a.active()) return false;
  read_generic_array(a, index, out);
  return true;
}

void check_generic_arrays(const Context& ctx, bool& mapped, size_t& elements) {
  const bool program = ctx.programs.active() != nullptr;
  for (int i = 0; i < kMaxVertexAttribs; ++i) {
    const GenericArray& a = ctx.programs.arrays[i];
    if (!a.active() || !a.buffer || (i > 0 && !program)) continue;
    mapped |= a.buffer->mapped;
    const size_t bytes = size_t(gl_type_size(a.type)) * size_t(a.size);  // generic_element's test
    elements = std::min(elements, elements_inside(*a.buffer, reinterpret_cast<uintptr_t>(a.pointer),
                                                  a.stride ? size_t(a.stride) : bytes, bytes));
  }
}

void capture_immediate_generics(Context& ctx, raster::VertexInput& v, const size_t* array_element) {
  ProgramState& ps = ctx.programs;
  if (!ps.active()) return;
  const size_t slot = ps.immediate_generic.size() / (4 * kMaxVertexAttribs);
  ps.immediate_generic.resize(ps.immediate_generic.size() + 4 * kMaxVertexAttribs);
  float* out = ps.immediate_generic.data() + slot * 4 * kMaxVertexAttribs;
  for (int i = 0; i < kMaxVertexAttribs; ++i) {
    std::copy(ps.current_attrib[i].begin(), ps.current_attrib[i].end(), out + 4 * i);
    if (array_element && ps.arrays[i].active()) read_generic_array(ps.arrays[i], *array_element, out + 4 * i);
  }
  std::copy(v.position, v.position + 4, out);
  v.source = static_cast<uint32_t>(slot);
}

void fetch_generic(const Context& ctx, AttribSource source, const raster::VertexInput& v, int index, float out[4]) {
  const ProgramState& ps = ctx.programs;
  if (index == 0) {
    std::copy(v.position, v.position + 4, out);
    return;
  }
  std::copy(ps.current_attrib[index].begin(), ps.current_attrib[index].end(), out);
  switch (source) {
    case AttribSource::Arrays: return fetch_generic_element(ctx, index, v.source, out);
    case AttribSource::Immediate: {
      const size_t at = (size_t(v.source) * kMaxVertexAttribs + size_t(index)) * 4;
      if (v.source != UINT32_MAX && at + 4 <= ps.immediate_generic.size())
        std::copy(ps.immediate_generic.begin() + at, ps.immediate_generic.begin() + at + 4, out);
      return;
    }
    case AttribSource::Current: return;
  }
}

}  // namespace pineda
