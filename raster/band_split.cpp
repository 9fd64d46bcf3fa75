#include "raster/band_split.h"

#include <algorithm>
#include <numeric>

namespace pineda::raster {

void BandSplit::reset(int rows, int bands) {
  row_cost_.assign(static_cast<size_t>(std::max(rows, 0)), rows > 0 ? 1.0 / rows : 0.0);
  starts_.assign(static_cast<size_t>(std::clamp(bands, 1, std::max(rows, 1))) + 1, 0);
  split();
}

void BandSplit::record(std::span<const double> times) {
  const int n = bands();
  if (static_cast<int>(times.size()) != n) return;
  const double total = std::accumulate(times.begin(), times.end(), 0.0);
  if (!(total > 0.0)) return;
  for (int b = 0; b < n; ++b) {
    const double per_row = times[static_cast<size_t>(b)] / total / (end(b) - first(b));
    for (int r = first(b); r < end(b); ++r) row_cost_[static_cast<size_t>(r)] = 0.5 * row_cost_[static_cast<size_t>(r)] + 0.5 * per_row;
  }
  split();
}

// Band b ends at the first row where the cost so far reaches (b + 1) / bands of the whole,
// leaving at least one row for each band after it.
void BandSplit::split() {
  const int rows = static_cast<int>(row_cost_.size()), n = bands();
  const double total = std::accumulate(row_cost_.begin(), row_cost_.end(), 0.0);
  starts_.front() = 0;
  starts_.back() = rows;
  double sum = 0.0;
  int row = 0;
  for (int b = 0; b + 1 < n; ++b) {
    const double goal = total * (b + 1) / n;
    // At least one row in this band; at least one left for each later band.
    do sum += row_cost_[static_cast<size_t>(row++)];
    while (row < rows - (n - 1 - b) && sum + row_cost_[static_cast<size_t>(row)] / 2 <= goal);
    starts_[static_cast<size_t>(b) + 1] = row;
  }
}

}  // namespace pineda::raster
