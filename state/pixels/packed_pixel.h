// GL 1.2's packed pixel types (GL 1.5 spec table 3.8): a whole pixel in one byte, short or
// int, its components in bit fields.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>

namespace pineda {

struct PackedLayout {
  int bytes;       // 1, 2 or 4
  int components;  // 3 or 4
  int bits[4];     // per component, in the format's order
  bool reversed;   // _REV: the first component in the least significant bits
};

// The layout of a packed type, or null when `type` is not one.
const PackedLayout* packed_layout(GLenum type);

// The components of one packed pixel as normalized values in [0, 1], in the format's order.
void unpack_components(const uint8_t* src, const PackedLayout& layout, float out[4]);
// Writes components in [0, 1] (the format's order) as one packed pixel.
void pack_components(const double in[4], const PackedLayout& layout, uint8_t* dst);

}  // namespace pineda
