// Generic vertex attributes for draws with a program: where each vertex's values come from,
// and reading them out of the arrays or the values captured between glBegin and glEnd.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "raster/vertex.h"

namespace pineda {

class Context;
struct GenericArray;

// Where the generic attributes of a draw's vertices are (VertexInput::source says which
// element or slot): array elements (glDrawArrays/Elements), the slots captured in immediate
// mode, or only the current values (display lists, evaluators).
enum class AttribSource : uint8_t { Arrays, Immediate, Current };

// Called for each vertex glBegin/glEnd collects: with a program in use, its generic
// attributes are captured (the current values, or the arrays' element `array_element`).
void capture_immediate_generics(Context& ctx, raster::VertexInput& v, const size_t* array_element = nullptr);

// Generic attribute `index` of `v` (index 0 is the position).
void fetch_generic(const Context& ctx, AttribSource source, const raster::VertexInput& v, int index, float out[4]);

// Generic attribute `index` of array element `element` (AttribSource::Arrays): what
// fetch_generic gives for the vertex fetched from that element.
void fetch_generic_element(const Context& ctx, int index, size_t element, float out[4]);

// An enabled generic array of GL_FLOAT or normalized GL_UNSIGNED_BYTE (colours) elements,
// resolved once per draw so that each element is read straight from memory: the same values
// fetch_generic gives.
struct DirectArrayView {
  const uint8_t* base = nullptr;
  size_t stride = 0;
  size_t count = 0;               // elements inside the buffer object (SIZE_MAX in client memory)
  int size = 4;
  bool unorm8 = false;             // normalized GL_UNSIGNED_BYTE components (else GL_FLOAT)
  const float* current = nullptr;  // the attribute's current value, for elements outside the buffer
  // Inline, with a copy of constant size per case: the vertex shader's input loop calls it per
  // vertex and attribute (a variable-size memcpy became a library call).
  void read(size_t index, float out[4]) const {
    if (index >= count) {
      std::memcpy(out, current, sizeof(float) * 4);
      return;
    }
    const uint8_t* element = base + stride * index;
    out[0] = out[1] = out[2] = 0.f;
    out[3] = 1.f;
    if (unorm8) {
      for (int c = 0; c < size; ++c) out[c] = element[c] / 255.f;  // read_vertex_component's
      return;
    }
    switch (size) {
      case 4: std::memcpy(out, element, sizeof(float) * 4); break;
      case 3: std::memcpy(out, element, sizeof(float) * 3); break;
      case 2: std::memcpy(out, element, sizeof(float) * 2); break;
      default: std::memcpy(out, element, sizeof(float)); break;
    }
  }
};

// Whether generic attribute `index` of a draw from `source` is read from an array directly; if
// so, `out` is its view.
bool direct_array_view(const Context& ctx, AttribSource source, int index, DirectArrayView& out);

// The bytes of element `index` of a generic array, null outside its buffer object.
const uint8_t* generic_element(const GenericArray& a, size_t index);

// Generic array 0 aliases the vertex array (GL 2.0 2.7): when enabled, element `index` is the
// position. False when it is disabled.
bool read_generic_position(const Context& ctx, size_t index, float out[4]);

// Whether an enabled generic array (that the draw reads) is backed by a mapped buffer; `elements`
// lowered to how many elements each such array's buffer holds.
void check_generic_arrays(const Context& ctx, bool& mapped, size_t& elements);

}  // namespace pineda
