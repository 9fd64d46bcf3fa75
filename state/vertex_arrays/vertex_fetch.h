// Reading vertices out of the application's client arrays.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <cstring>

#include "raster/vertex.h"

namespace pineda {

class Context;
struct ClientArray;

// Builds vertex `index` from the enabled client arrays, taking the current values for
// disabled ones (VertexFetchPlan's fetch; build one plan for many vertices).
void fetch_vertex(const Context& ctx, size_t index, raster::VertexInput& out);

// Vertex `index` as a draw whose vertex shader reads generic attributes alone needs it: its
// element (the shader reads the generic arrays through `source`), its position (generic
// attribute 0) and edge flag, the other values at their defaults.
void fetch_vertex_source(const Context& ctx, size_t index, raster::VertexInput& out);

// The position of array element `index` as fetch_vertex reads it (generic array 0, else the
// vertex array, else in OpenGL ES 2.0 the current value of attribute 0); `position` keeps its
// values where none of them gives one.
void fetch_array_position(const Context& ctx, size_t index, float position[4]);

// The edge flag of array element `index`: the edge flag array's, else the current one.
bool array_edge_flag(const Context& ctx, size_t index);

// Whether the program in use has a vertex shader that reads no built-in attribute (gl_Vertex,
// gl_Color, ...): its draws' vertices need only fetch_vertex_source.
bool vertex_shader_reads_generic_attributes_only(const Context& ctx);

// The colour index of element `index` of the index array, or the current index when that
// array is disabled.
float fetch_index(const Context& ctx, size_t index);

// glArrayElement's effect on the current index: element `index` of the index array becomes it
// when that array is enabled.
void take_current_index(Context& ctx, size_t index);

// The `bytes` bytes of element `index` of `array`: in client memory, or in its buffer object
// (null when they are not all inside the buffer's store).
const uint8_t* array_element(const ClientArray& array, size_t index, size_t bytes);

// One component of type `type` at p as a float; `normalize` maps integers to [0, 1] or [-1, 1].
float read_vertex_component(const uint8_t* p, unsigned type, bool normalize);

// Byte size of one component of a GL array type, 0 when the type is not one.
int gl_type_size(unsigned type);

// `size` components of type `type` at p into dst, as read_vertex_component reads each. Inline,
// with the common cases first: it runs once per array and vertex.
inline void read_components(const uint8_t* p, unsigned type, int size, bool normalize, float* dst) {
  if (type == GL_FLOAT) {  // copies of constant size, without a conversion per component
    switch (size) {
      case 4: std::memcpy(dst, p, sizeof(float) * 4); return;
      case 3: std::memcpy(dst, p, sizeof(float) * 3); return;
      case 2: std::memcpy(dst, p, sizeof(float) * 2); return;
      case 1: std::memcpy(dst, p, sizeof(float)); return;
      default: break;
    }
  }
  if (type == GL_UNSIGNED_BYTE && normalize) {  // colours as bytes: read_vertex_component's values
    for (int c = 0; c < size; ++c) dst[c] = p[c] / 255.f;
    return;
  }
  const int component = gl_type_size(type);
  for (int c = 0; c < size; ++c) dst[c] = read_vertex_component(p + c * component, type, normalize);
}

}  // namespace pineda
