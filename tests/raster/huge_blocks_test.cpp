// Huge blocks: on a 2 MiB boundary, zero, writable to their last byte, apart from each other, and
// a size no mapping can hold refused with std::bad_alloc.
#include "raster/huge_blocks.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <new>

namespace pineda::raster {
namespace {

TEST(HugeBlocks, StartOnAHugePageZeroAndWritableToTheirEnd) {
  for (size_t bytes : {size_t{1}, kHugePageBytes - 1, kHugePageBytes, kHugePageBytes + 1, size_t{5} << 20}) {
    auto* a = static_cast<uint8_t*>(map_huge_block(bytes));
    auto* b = static_cast<uint8_t*>(map_huge_block(bytes));
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(a) % kHugePageBytes, 0u) << bytes;
    EXPECT_TRUE(a + bytes <= b || b + bytes <= a) << bytes;
    uint64_t sum = 0;
    for (size_t i = 0; i < bytes; i += 4096) sum += a[i];
    EXPECT_EQ(sum + a[bytes - 1], 0u) << bytes;
    a[0] = 1;
    a[bytes - 1] = 2;
    b[bytes - 1] = 3;
    EXPECT_EQ(a[bytes - 1] + b[bytes - 1], 5) << bytes;
    unmap_huge_block(a, bytes);
    unmap_huge_block(b, bytes);
  }
  unmap_huge_block(nullptr, 10);
}

TEST(HugeBlocks, ASizeNoMappingHoldsIsRefused) {
  EXPECT_THROW(map_huge_block(SIZE_MAX), std::bad_alloc);
  EXPECT_THROW(map_huge_block(SIZE_MAX - kHugePageBytes), std::bad_alloc);
  EXPECT_THROW(map_huge_block(size_t{1} << 62), std::bad_alloc);
}

}  // namespace
}  // namespace pineda::raster
