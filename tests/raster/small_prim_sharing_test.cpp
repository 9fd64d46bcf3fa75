// The choice between sharing scenes of small primitives and rasterizing them where binned.
#include "raster/small_prim_sharing.h"

#include <gtest/gtest.h>

namespace pineda::raster {
namespace {

TEST(SmallPrimSharing, MeasuresBothWaysFirst) {
  SmallPrimSharing s;
  EXPECT_FALSE(s.share());  // rasterized where binned until measured
  s.record(false, 100000.0, 1000);
  EXPECT_TRUE(s.share());  // then shared until measured
  s.record(true, 300000.0, 1000);
  EXPECT_FALSE(s.share());  // 100 ns a primitive where binned against 300 shared
  EXPECT_DOUBLE_EQ(s.ns_per_prim(false), 100.0);
  EXPECT_DOUBLE_EQ(s.ns_per_prim(true), 300.0);
}

TEST(SmallPrimSharing, TakesTheFasterWayAndRetriesTheOther) {
  SmallPrimSharing s;
  s.record(false, 100000.0, 1000);
  s.record(true, 50000.0, 1000);
  int shared = 0, local = 0;
  for (int i = 0; i < 4 * SmallPrimSharing::kRetryEvery; ++i) {
    const bool way = s.share();
    (way ? shared : local) += 1;
    s.record(way, way ? 50000.0 : 100000.0, 1000);
  }
  EXPECT_EQ(local, 4);  // one retry in every kRetryEvery scenes
  EXPECT_EQ(shared, 4 * SmallPrimSharing::kRetryEvery - 4);
}

TEST(SmallPrimSharing, FollowsAChangeOfTheMachine) {
  SmallPrimSharing s;
  s.record(false, 70000.0, 1000);
  s.record(true, 50000.0, 1000);
  EXPECT_TRUE(s.share());
  // Sharing becomes dear (another tenant): the running average moves by a quarter a sample.
  s.record(true, 150000.0, 1000);
  EXPECT_DOUBLE_EQ(s.ns_per_prim(true), 75.0);
  EXPECT_FALSE(s.share());
}

TEST(SmallPrimSharing, IgnoresEmptyScenes) {
  SmallPrimSharing s;
  s.record(false, 1000.0, 0);
  EXPECT_FALSE(s.share());
  EXPECT_DOUBLE_EQ(s.ns_per_prim(false), 0.0);
}

}  // namespace
}  // namespace pineda::raster
