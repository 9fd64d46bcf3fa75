// Parallel binning's bands: equal at first, then following the rows' measured costs, never empty.
#include <gtest/gtest.h>

#include <vector>

#include "raster/band_split.h"

namespace pineda::raster::test {
namespace {

std::vector<int> starts(const BandSplit& split) {
  std::vector<int> s;
  for (int b = 0; b < split.bands(); ++b) s.push_back(split.first(b));
  s.push_back(split.end(split.bands() - 1));
  return s;
}

// Each band's time when row r costs cost[r].
std::vector<double> band_times(const BandSplit& split, const std::vector<double>& cost) {
  std::vector<double> t;
  for (int b = 0; b < split.bands(); ++b) {
    double sum = 0;
    for (int r = split.first(b); r < split.end(b); ++r) sum += cost[static_cast<size_t>(r)];
    t.push_back(sum);
  }
  return t;
}

TEST(BandSplit, StartsEqualAndMovesTowardEqualTimes) {
  BandSplit split;
  split.reset(12, 2);
  EXPECT_EQ(starts(split), (std::vector<int>{0, 6, 12}));
  // Rows 0-5 three times as dear as rows 6-11: equal halves at 4 rows | 8 rows (12 | 12).
  const std::vector<double> cost{3, 3, 3, 3, 3, 3, 1, 1, 1, 1, 1, 1};
  split.record(band_times(split, cost));
  EXPECT_EQ(starts(split), (std::vector<int>{0, 5, 12}));  // halfway there after one draw
  for (int i = 0; i < 10; ++i) split.record(band_times(split, cost));
  EXPECT_EQ(starts(split), (std::vector<int>{0, 4, 12}));
}

TEST(BandSplit, ThreeBandsFollowAHotSpot) {
  BandSplit split;
  split.reset(9, 3);
  EXPECT_EQ(starts(split), (std::vector<int>{0, 3, 6, 9}));
  const std::vector<double> cost{1, 1, 1, 1, 10, 1, 1, 1, 1};  // one row of 10 in 18
  for (int i = 0; i < 20; ++i) split.record(band_times(split, cost));
  // The dear row alone is more than a third: its band holds it and little else.
  const std::vector<int> s = starts(split);
  EXPECT_EQ(s[1], 4);
  EXPECT_EQ(s[2], 5);
}

TEST(BandSplit, BandsNeverEmptyAndBadTimesChangeNothing) {
  BandSplit split;
  split.reset(4, 4);
  EXPECT_EQ(starts(split), (std::vector<int>{0, 1, 2, 3, 4}));
  split.record(std::vector<double>{100, 0, 0, 0});
  EXPECT_EQ(starts(split), (std::vector<int>{0, 1, 2, 3, 4}));
  split.reset(6, 2);
  for (int i = 0; i < 10; ++i) split.record(std::vector<double>{0, 5});
  EXPECT_EQ(starts(split), (std::vector<int>{0, 5, 6}));
  split.record(std::vector<double>{0, 0});     // no time: kept
  split.record(std::vector<double>{1, 1, 1});  // not one per band: kept
  EXPECT_EQ(starts(split), (std::vector<int>{0, 5, 6}));
  split.reset(0, 2);
  EXPECT_EQ(split.bands(), 1);
}

}  // namespace
}  // namespace pineda::raster::test
