#include "image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace pineda::tools {

ImageDifference compareImages(const Image& a, const Image& b, Image* diff) {
  if (diff) {
    diff->width = a.width;
    diff->height = a.height;
    diff->rgba.assign(a.rgba.size(), 0);
  }
  ImageDifference result;
  long within1 = 0, within8 = 0, differing = 0;
  double squaredError = 0;
  const long pixels = long(a.width) * a.height;
  for (long p = 0; p < pixels; ++p) {
    const std::uint8_t* pa = &a.rgba[p * 4];
    const std::uint8_t* pb = &b.rgba[p * 4];
    int pixelMax = 0;
    for (int c = 0; c < 4; ++c) {
      int d = std::abs(int(pa[c]) - int(pb[c]));
      pixelMax = std::max(pixelMax, d);
      squaredError += double(d) * d;
    }
    result.maxDiff = std::max(result.maxDiff, pixelMax);
    within1 += pixelMax <= 1;
    within8 += pixelMax <= 8;
    differing += pixelMax > 0;
    if (diff) {
      std::uint8_t* out = &diff->rgba[p * 4];
      if (pixelMax == 0) {
        auto grey = std::uint8_t((pa[0] * 3 + pa[1] * 6 + pa[2]) / 40);
        out[0] = out[1] = out[2] = grey;
      } else {
        out[0] = std::uint8_t(std::min(255, 96 + pixelMax * 8));
        out[1] = pixelMax <= 1 ? 96 : 0;
        out[2] = 0;
      }
      out[3] = 255;
    }
  }
  const double count = std::max(1.0, double(pixels));
  result.within1Share = within1 / count;
  result.within8Share = within8 / count;
  result.differShare = differing / count;
  const double mse = squaredError / (count * 4);
  result.psnr = mse == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
  return result;
}

}  // namespace pineda::tools
