// Buffers rendered into start on a cache line, whatever their size (glibc's own large blocks
// start 16 bytes past one).
#include "raster/cache_line_vector.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace pineda::raster {
namespace {

template <typename T>
void expect_lines_for_sizes() {
  for (size_t n : {size_t{1}, size_t{3}, size_t{64}, size_t{1000}, size_t{1024} * 768, size_t{3} << 20}) {
    CacheLineVector<T> v(n, T{7});
    EXPECT_EQ(reinterpret_cast<uintptr_t>(v.data()) % 64, 0u) << n;
    EXPECT_EQ(v[n - 1], T{7});
    v.resize(n * 2 + 1);  // a reallocation keeps the alignment
    EXPECT_EQ(reinterpret_cast<uintptr_t>(v.data()) % 64, 0u) << n;
    EXPECT_EQ(v[n - 1], T{7});
  }
}

TEST(CacheLineVector, StartsOnACacheLine) {
  expect_lines_for_sizes<uint8_t>();
  expect_lines_for_sizes<uint32_t>();
}

TEST(CacheLineVector, CopiesAndComparesAsAVector) {
  CacheLineVector<uint32_t> a{1, 2, 3};
  CacheLineVector<uint32_t> b = a;
  EXPECT_EQ(a, b);
  b[1] = 5;
  EXPECT_NE(a, b);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(b.data()) % 64, 0u);
}

}  // namespace
}  // namespace pineda::raster
