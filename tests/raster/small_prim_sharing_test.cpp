// The choice between sharing scenes of small primitives and rasterizing them where binned.
#include "raster/small_prim_sharing.h"

#include <gtest/gtest.h>

#include <vector>

namespace pineda::raster {
namespace {

constexpr int kCounted = SmallPrimSharing::kWarmUpScenes + 1;  // scenes of a new way until one counts

// Scenes of one way until a sample of it counts.
void measure(SmallPrimSharing& s, bool shared, double ns, size_t prims) {
  for (int i = 0; i < kCounted; ++i) s.record(shared, ns, prims);
}

TEST(SmallPrimSharing, MeasuresBothWaysFirst) {
  SmallPrimSharing s;
  EXPECT_FALSE(s.share());  // rasterized where binned until measured
  measure(s, false, 100000.0, 1000);
  EXPECT_TRUE(s.share());  // then shared until measured
  measure(s, true, 300000.0, 1000);
  EXPECT_FALSE(s.share());  // 100 ns a primitive where binned against 300 shared
  EXPECT_DOUBLE_EQ(s.ns_per_prim(false), 100.0);
  EXPECT_DOUBLE_EQ(s.ns_per_prim(true), 300.0);
}

TEST(SmallPrimSharing, TheFirstScenesOfANewWayDoNotCount) {
  SmallPrimSharing s;
  measure(s, false, 100000.0, 1000);
  // A thread taking scenes over starts cold: those samples are left out, the way is held.
  for (int i = 0; i < SmallPrimSharing::kWarmUpScenes; ++i) {
    EXPECT_TRUE(s.share());
    s.record(true, 900000.0, 1000);
    EXPECT_DOUBLE_EQ(s.ns_per_prim(true), 0.0);
  }
  s.record(true, 60000.0, 1000);
  EXPECT_DOUBLE_EQ(s.ns_per_prim(true), 60.0);
  EXPECT_TRUE(s.share());  // 60 ns shared against 100 where binned
  // Back where binned: again only from the third scene on.
  s.record(false, 500000.0, 1000);
  s.record(false, 500000.0, 1000);
  EXPECT_DOUBLE_EQ(s.ns_per_prim(false), 100.0);
  s.record(false, 500000.0, 1000);
  EXPECT_DOUBLE_EQ(s.ns_per_prim(false), 200.0);  // a quarter of the way to 500
}

TEST(SmallPrimSharing, TakesTheFasterWayAndRetriesTheOther) {
  SmallPrimSharing s;
  measure(s, false, 100000.0, 1000);
  measure(s, true, 50000.0, 1000);
  std::vector<int> local_runs;  // lengths of the runs of scenes rasterized where binned
  int shared = 0, run = 0;
  for (int i = 0; i < 4 * SmallPrimSharing::kRetryEvery; ++i) {
    const bool way = s.share();
    if (way) {
      ++shared;
      if (run) local_runs.push_back(run);
      run = 0;
    } else {
      ++run;
    }
    s.record(way, way ? 50000.0 : 100000.0, 1000);
  }
  // Each retry runs until one sample counts (three scenes), then sharing until the next retry
  // is due: 64 counted samples after the last, two more scenes for sharing's own warm-up.
  EXPECT_EQ(local_runs, (std::vector<int>{kCounted, kCounted, kCounted}));
  EXPECT_EQ(shared, 4 * SmallPrimSharing::kRetryEvery - 3 * kCounted);
}

TEST(SmallPrimSharing, FollowsAChangeOfTheMachine) {
  SmallPrimSharing s;
  measure(s, false, 70000.0, 1000);
  measure(s, true, 50000.0, 1000);
  EXPECT_TRUE(s.share());
  // Sharing becomes dear (another tenant): the running average moves by a quarter a sample.
  s.record(true, 150000.0, 1000);
  EXPECT_DOUBLE_EQ(s.ns_per_prim(true), 75.0);
  EXPECT_FALSE(s.share());
}

TEST(SmallPrimSharing, IgnoresEmptyScenes) {
  SmallPrimSharing s;
  for (int i = 0; i < kCounted; ++i) s.record(false, 1000.0, 0);
  EXPECT_FALSE(s.share());
  EXPECT_DOUBLE_EQ(s.ns_per_prim(false), 0.0);
}

}  // namespace
}  // namespace pineda::raster
