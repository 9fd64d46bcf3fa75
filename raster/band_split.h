// Where parallel binning's bands (parallel_binning.h) meet: tile rows split among the threads so
// that each band takes about as long. Each row's share of a draw's time is estimated from the
// bands' last times (a band's time spread evenly over its rows, averaged with the earlier
// estimate), and the rows are split again by it after every draw: a model at the top of the
// screen, whose rows hold most of the work, gets narrower bands there. Which thread draws a
// row never changes the image, so the split may follow the clock.
#pragma once
#include <span>
#include <vector>

namespace pineda::raster {

class BandSplit {
 public:
  // `rows` tile rows in `bands` bands (1 <= bands <= rows), of equal estimated cost at first.
  void reset(int rows, int bands);
  int bands() const { return static_cast<int>(starts_.size()) - 1; }
  // Band i: tile rows [first(i), end(i)), never empty.
  int first(int band) const { return starts_[static_cast<size_t>(band)]; }
  int end(int band) const { return starts_[static_cast<size_t>(band) + 1]; }
  // Each band's time in the last draw (bands() values, any unit); splits the rows again.
  void record(std::span<const double> times);

 private:
  void split();
  std::vector<double> row_cost_;  // each row's estimated share of a draw's time
  std::vector<int> starts_;       // bands() + 1 row numbers, from 0 to the row count
};

}  // namespace pineda::raster
