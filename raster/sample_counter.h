// Occlusion-query counting: the samples of the draws that carry a counter and pass every
// fragment test up to and including depth. Tiles add their exact integer sums, so the total
// is the same for any thread count.
#pragma once
#include <atomic>
#include <cstdint>

namespace pineda::raster {

struct SampleCounter {
  std::atomic<uint64_t> passed{0};
};

}  // namespace pineda::raster
