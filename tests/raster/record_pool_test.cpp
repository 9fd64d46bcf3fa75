// RecordPool: records in pieces of its slabs, distinct and aligned however many are alive, a
// released piece taken again, other sizes from the heap, records released on other threads, and
// the pool kept alive by its records after its renderer lets go of it (and freed with the last:
// the sanitizer build's leak check).
#include "raster/record_pool.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <thread>
#include <vector>

namespace pineda::raster {
namespace {

DrawRecord record_with_units(int units) {
  DrawRecord r;
  r.num_units = units;
  return r;
}

TEST(RecordPool, RecordsAreDistinctAlignedAndKeepTheirValuesPastTheFirstSlabs) {
  const RecordPoolHandle pool = make_record_pool();
  std::vector<std::shared_ptr<const DrawRecord>> records;
  std::set<const DrawRecord*> addresses;
  for (int i = 0; i < 3000; ++i) {  // past the first slab and the first huge one
    records.push_back(make_pooled_record(pool.get(), record_with_units(i % 5)));
    addresses.insert(records.back().get());
    EXPECT_EQ(reinterpret_cast<uintptr_t>(records.back().get()) % alignof(DrawRecord), 0u);
  }
  EXPECT_EQ(addresses.size(), records.size());
  for (int i = 0; i < 3000; ++i) ASSERT_EQ(records[static_cast<size_t>(i)]->num_units, i % 5) << i;
}

TEST(RecordPool, AReleasedPieceIsTakenAgainAndOtherSizesComeFromTheHeap) {
  const RecordPoolHandle handle = make_record_pool();
  RecordPool& pool = *handle;
  void* a = pool.take(1000);
  void* b = pool.take(1000);
  EXPECT_NE(a, b);
  pool.give_back(a, 1000);
  EXPECT_EQ(pool.take(1000), a);
  void* other = pool.take(5000);  // not the pool's piece size
  ASSERT_NE(other, nullptr);
  static_cast<char*>(other)[4999] = 1;
  pool.give_back(other, 5000);
  pool.give_back(a, 1000);
  pool.give_back(b, 1000);
  pool.give_back(nullptr, 1000);
}

TEST(RecordPool, RecordsReleasedOnOtherThreadsOutliveTheRenderersHold) {
  RecordPoolHandle pool = make_record_pool();
  std::vector<std::shared_ptr<const DrawRecord>> first, second;
  for (int i = 0; i < 2000; ++i) (i % 2 ? first : second).push_back(make_pooled_record(pool.get(), record_with_units(1)));
  pool.reset();  // the renderer is gone; its records keep the pool
  std::thread a([&] { first.clear(); });
  std::thread b([&] { second.clear(); });
  a.join();
  b.join();
  EXPECT_TRUE(first.empty() && second.empty());
}

}  // namespace
}  // namespace pineda::raster
