// The bytes a call writes into client memory given a size, with guard bytes after it: shows
// that the glGetn*/glReadn* getters of the robustness extensions write nothing past bufSize.
#pragma once
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pineda::test {

inline constexpr uint8_t kGuard = 0xCD;

// Runs `call` with a buffer of `size` bytes plus guard bytes; the bytes it wrote. A byte written
// past `size` fails the test.
template <typename Call>
std::vector<uint8_t> written(size_t size, Call call) {
  std::vector<uint8_t> buffer(size + 16, kGuard);
  call(buffer.data());
  for (size_t i = size; i < buffer.size(); ++i) EXPECT_EQ(buffer[i], kGuard) << "byte " << i << " past bufSize";
  buffer.resize(size);
  return buffer;
}

}  // namespace pineda::test
