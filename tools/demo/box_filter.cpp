#include "box_filter.h"

namespace pineda::demo {

Texels halve(const Texels& level, int size, int channels) {
  int half = size / 2;
  Texels out(std::size_t(half) * half * channels);
  for (int y = 0; y < half; ++y)
    for (int x = 0; x < half; ++x)
      for (int c = 0; c < channels; ++c) {
        auto at = [&](int sx, int sy) { return int(level[(std::size_t(sy) * size + sx) * channels + c]); };
        int sum = at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1);
        out[(std::size_t(y) * half + x) * channels + c] = std::uint8_t((sum + 2) / 4);
      }
  return out;
}

}  // namespace pineda::demo
