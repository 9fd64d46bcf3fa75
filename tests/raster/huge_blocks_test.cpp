// Huge blocks: on a 2 MiB boundary, zero, writable to their last byte, apart from each other, and
// a size no mapping can hold refused with std::bad_alloc.
#include "raster/huge_blocks.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <new>
#include <set>
#include <vector>

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

TEST(HugeBlocks, AReleasedBlockIsTakenAgainForTheSameSizeAndFourAreKept) {
  constexpr size_t kBytes = (size_t{6} << 20) + 123;  // a size no other test releases
  std::vector<void*> released;  // in the order they are released
  for (int i = 0; i < 5; ++i) {
    void* b = take_huge_block(kBytes);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(b) % kHugePageBytes, 0u);
    static_cast<uint8_t*>(b)[kBytes - 1] = static_cast<uint8_t>(i + 1);
    released.push_back(b);
  }
  EXPECT_EQ(std::set<void*>(released.begin(), released.end()).size(), 5u);
  for (void* b : released) release_huge_block(b, kBytes);
  void* other = take_huge_block(kHugePageBytes);  // another size: none of the kept (all four come back below)
  // A kept block comes back as it was left; a new mapping (maybe at a freed block's address) is zero.
  std::set<int> kept_marks;
  std::vector<void*> taken;
  for (int i = 0; i < 5; ++i) {
    taken.push_back(take_huge_block(kBytes));
    uint8_t& last = static_cast<uint8_t*>(taken.back())[kBytes - 1];
    if (last != 0) kept_marks.insert(last);
    last = 9;  // writable to its end
  }
  EXPECT_EQ(kept_marks, (std::set<int>{2, 3, 4, 5}));  // the eldest of the five was unmapped
  for (void* b : taken) release_huge_block(b, kBytes);
  release_huge_block(other, kHugePageBytes);
  release_huge_block(nullptr, kBytes);
}

}  // namespace
}  // namespace pineda::raster
