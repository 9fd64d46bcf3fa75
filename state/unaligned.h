// Values read from and written to byte buffers at any alignment: client arrays, images,
// list names. memcpy is the defined way; compilers turn it into a plain load or store.
#pragma once
#include <cstdint>
#include <cstring>

namespace pineda {

template <typename T>
T load_unaligned(const uint8_t* src) {
  T v;
  std::memcpy(&v, src, sizeof v);
  return v;
}

template <typename T>
void store_unaligned(uint8_t* dst, T v) {
  std::memcpy(dst, &v, sizeof v);
}

}  // namespace pineda
