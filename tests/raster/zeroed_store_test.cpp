// ZeroedStore: new elements zero, earlier ones kept through growth, no reallocation when the
// room suffices, and a large store's elements all writable.
#include <gtest/gtest.h>

#include <cstdint>

#include "raster/zeroed_store.h"

namespace pineda::raster {
namespace {

struct Element {
  uint32_t a;
  float b[3];
  bool flag = false;
};

TEST(ZeroedStore, GrowsKeepingEarlierElementsAndZeroingNewOnes) {
  ZeroedStore<Element> store;
  EXPECT_EQ(store.data(), nullptr);
  EXPECT_EQ(store.capacity(), 0u);
  Element* first = store.grow(3);
  ASSERT_NE(first, nullptr);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(first[i].a, 0u);
    EXPECT_EQ(first[i].b[2], 0.f);
    EXPECT_FALSE(first[i].flag);
    first[i] = {static_cast<uint32_t>(i + 1), {1.f, 2.f, 3.f}, true};
  }
  EXPECT_EQ(store.grow(2), first);  // room enough: the same elements
  EXPECT_EQ(store.capacity(), 3u);
  Element* grown = store.grow(5);
  EXPECT_EQ(store.capacity(), 5u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(grown[i].a, static_cast<uint32_t>(i + 1));
    EXPECT_EQ(grown[i].b[1], 2.f);
    EXPECT_TRUE(grown[i].flag);
  }
  for (int i = 3; i < 5; ++i) {
    EXPECT_EQ(grown[i].a, 0u);
    EXPECT_FALSE(grown[i].flag);
  }
}

TEST(ZeroedStore, ALargeStoreIsZeroAndWritableToItsEnd) {
  ZeroedStore<uint64_t> store;
  constexpr size_t kCount = (size_t{5} << 20) / sizeof(uint64_t) + 3;  // over two 2 MiB pieces
  uint64_t* p = store.grow(kCount);
  uint64_t sum = 0;
  for (size_t i = 0; i < kCount; i += 512) sum += p[i];
  EXPECT_EQ(sum, 0u);
  p[kCount - 1] = 7;
  p[0] = 5;
  EXPECT_EQ(store.grow(kCount)[kCount - 1] + store.data()[0], 12u);
}

}  // namespace
}  // namespace pineda::raster
