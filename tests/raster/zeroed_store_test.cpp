// ZeroedStore: new elements zero, earlier ones kept through growth, no reallocation when the
// room suffices, a large store's elements all writable, and a move leaves the source empty (the
// renderer swaps its two scenes, each holding one).
#include <gtest/gtest.h>

#include <cstdint>
#include <utility>

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

TEST(ZeroedStore, KeepsItsElementsFromSmallPagesIntoAHugeBlockAndBetweenHugeBlocks) {
  ZeroedStore<uint64_t> store;
  uint64_t* p = store.grow(1000);
  for (size_t i = 0; i < 1000; ++i) p[i] = i * 3 + 1;
  const size_t huge = kHugeStoreBytes / sizeof(uint64_t) + 5;
  const size_t larger = (size_t{3} << 20) / sizeof(uint64_t);
  for (size_t count : {huge, larger}) {
    p = store.grow(count);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(p) % kHugePageBytes, 0u) << count;
    for (size_t i = 0; i < 1000; ++i) ASSERT_EQ(p[i], i * 3 + 1) << count;
    EXPECT_EQ(p[1000] + p[count - 1], 0u) << count;
    p[count - 1] = 11;
  }
  EXPECT_EQ(p[huge - 1], 11u);
  ZeroedStore<uint64_t> moved(std::move(store));
  EXPECT_EQ(moved.data()[larger - 1] + moved.data()[999], 11u + 2998u);
  EXPECT_EQ(store.data(), nullptr);
}

TEST(ZeroedStore, AMoveLeavesTheSourceEmptyAndAbleToGrow) {
  ZeroedStore<int> a;
  int* p = a.grow(4);
  p[3] = 9;
  ZeroedStore<int> b(std::move(a));
  EXPECT_EQ(b.data(), p);
  EXPECT_EQ(b.capacity(), 4u);
  EXPECT_EQ(a.data(), nullptr);
  EXPECT_EQ(a.capacity(), 0u);
  ASSERT_NE(a.grow(2), nullptr);  // room again, not the capacity it had
  EXPECT_EQ(a.data()[1], 0);
  a = std::move(b);
  EXPECT_EQ(a.data(), p);
  EXPECT_EQ(a.data()[3], 9);
  EXPECT_EQ(b.capacity(), 0u);
  EXPECT_EQ(b.data(), nullptr);
}

}  // namespace
}  // namespace pineda::raster
