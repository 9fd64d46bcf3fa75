#include "state/pixels/packed_pixel.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pineda {
namespace {

// Bit position of component `i`'s least significant bit.
int shift_of(const PackedLayout& l, int i) {
  int below = 0;  // bits of the components stored below component i
  if (l.reversed) {
    for (int c = 0; c < i; ++c) below += l.bits[c];
  } else {
    for (int c = i + 1; c < l.components; ++c) below += l.bits[c];
  }
  return below;
}

uint32_t load_element(const uint8_t* src, int bytes) {
  if (bytes == 1) return src[0];
  if (bytes == 2) {
    uint16_t v;
    std::memcpy(&v, src, 2);
    return v;
  }
  uint32_t v;
  std::memcpy(&v, src, 4);
  return v;
}

void store_element(uint32_t v, int bytes, uint8_t* dst) {
  if (bytes == 1) {
    dst[0] = uint8_t(v);
  } else if (bytes == 2) {
    const uint16_t s = uint16_t(v);
    std::memcpy(dst, &s, 2);
  } else {
    std::memcpy(dst, &v, 4);
  }
}

}  // namespace

const PackedLayout* packed_layout(GLenum type) {
  static constexpr PackedLayout k332{1, 3, {3, 3, 2, 0}, false}, k233r{1, 3, {3, 3, 2, 0}, true};
  static constexpr PackedLayout k565{2, 3, {5, 6, 5, 0}, false}, k565r{2, 3, {5, 6, 5, 0}, true};
  static constexpr PackedLayout k4444{2, 4, {4, 4, 4, 4}, false}, k4444r{2, 4, {4, 4, 4, 4}, true};
  static constexpr PackedLayout k5551{2, 4, {5, 5, 5, 1}, false}, k1555r{2, 4, {5, 5, 5, 1}, true};
  static constexpr PackedLayout k8888{4, 4, {8, 8, 8, 8}, false}, k8888r{4, 4, {8, 8, 8, 8}, true};
  static constexpr PackedLayout k1010102{4, 4, {10, 10, 10, 2}, false}, k2101010r{4, 4, {10, 10, 10, 2}, true};
  switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2: return &k332;
    case GL_UNSIGNED_BYTE_2_3_3_REV: return &k233r;
    case GL_UNSIGNED_SHORT_5_6_5: return &k565;
    case GL_UNSIGNED_SHORT_5_6_5_REV: return &k565r;
    case GL_UNSIGNED_SHORT_4_4_4_4: return &k4444;
    case GL_UNSIGNED_SHORT_4_4_4_4_REV: return &k4444r;
    case GL_UNSIGNED_SHORT_5_5_5_1: return &k5551;
    case GL_UNSIGNED_SHORT_1_5_5_5_REV: return &k1555r;
    case GL_UNSIGNED_INT_8_8_8_8: return &k8888;
    case GL_UNSIGNED_INT_8_8_8_8_REV: return &k8888r;
    case GL_UNSIGNED_INT_10_10_10_2: return &k1010102;
    case GL_UNSIGNED_INT_2_10_10_10_REV: return &k2101010r;
    default: return nullptr;
  }
}

void unpack_components(const uint8_t* src, const PackedLayout& l, float out[4]) {
  const uint32_t v = load_element(src, l.bytes);
  for (int i = 0; i < l.components; ++i) {
    const uint32_t max = (1u << l.bits[i]) - 1;
    out[i] = float(double((v >> shift_of(l, i)) & max) / max);
  }
}

void pack_components(const double in[4], const PackedLayout& l, uint8_t* dst) {
  uint32_t v = 0;
  for (int i = 0; i < l.components; ++i) {
    const uint32_t max = (1u << l.bits[i]) - 1;
    v |= uint32_t(std::lround(std::clamp(in[i], 0.0, 1.0) * max)) << shift_of(l, i);
  }
  store_element(v, l.bytes, dst);
}

}  // namespace pineda
