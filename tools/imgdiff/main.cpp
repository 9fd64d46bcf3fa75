// pineda-imgdiff A.png B.png [--diff OUT.png]: per-channel comparison of two images.
// Exit status: 0 when at least 99.9% of pixels are within 1/255 on every channel,
// 1 when they are not, 2 on error.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "png_io.h"

using pineda::tools::Image;

namespace {

constexpr double kPassShare = 0.999;

struct Stats {
  int maxDiff = 0;
  long within1 = 0;    // pixels whose every channel differs by at most 1
  long differing = 0;  // pixels with any channel differing
  double squaredError = 0;
};

// Identical pixels appear as a dimmed grey copy of A; differing ones in red, brighter for larger
// differences, so that small errors still stand out.
Stats compare(const Image& a, const Image& b, Image* diff) {
  Stats stats;
  const long pixels = long(a.width) * a.height;
  for (long p = 0; p < pixels; ++p) {
    const std::uint8_t* pa = &a.rgba[p * 4];
    const std::uint8_t* pb = &b.rgba[p * 4];
    int pixelMax = 0;
    for (int c = 0; c < 4; ++c) {
      int d = std::abs(int(pa[c]) - int(pb[c]));
      pixelMax = std::max(pixelMax, d);
      stats.squaredError += double(d) * d;
    }
    stats.maxDiff = std::max(stats.maxDiff, pixelMax);
    stats.within1 += pixelMax <= 1;
    stats.differing += pixelMax > 0;
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
  return stats;
}

}  // namespace

int main(int argc, char** argv) {
  std::string paths[2], diffPath;
  int count = 0;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--diff" && i + 1 < argc) {
      diffPath = argv[++i];
    } else if (arg.rfind("--", 0) != 0 && count < 2) {
      paths[count++] = arg;
    } else {
      count = -1;
      break;
    }
  }
  if (count != 2) {
    std::fprintf(stderr, "usage: pineda-imgdiff A.png B.png [--diff OUT.png]\n");
    return 2;
  }

  Image a, b;
  std::string error;
  if (!pineda::tools::readPng(paths[0], a, error) || !pineda::tools::readPng(paths[1], b, error)) {
    std::fprintf(stderr, "pineda-imgdiff: %s\n", error.c_str());
    return 2;
  }
  if (a.width != b.width || a.height != b.height) {
    std::fprintf(stderr, "pineda-imgdiff: sizes differ: %dx%d vs %dx%d\n", a.width, a.height, b.width,
                 b.height);
    return 2;
  }

  Image diff;
  if (!diffPath.empty()) {
    diff.width = a.width;
    diff.height = a.height;
    diff.rgba.resize(a.rgba.size());
  }
  Stats stats = compare(a, b, diffPath.empty() ? nullptr : &diff);
  if (!diffPath.empty() && !pineda::tools::writePng(diffPath, diff, error)) {
    std::fprintf(stderr, "pineda-imgdiff: %s\n", error.c_str());
    return 2;
  }

  const double pixels = std::max(1.0, double(a.width) * a.height);
  const double withinShare = stats.within1 / pixels;
  const double mse = stats.squaredError / (pixels * 4);
  std::printf("max channel difference: %d\n", stats.maxDiff);
  std::printf("pixels within 1/255: %.4f%%\n", 100.0 * withinShare);
  std::printf("pixels differing: %.4f%%\n", 100.0 * stats.differing / pixels);
  if (mse == 0)
    std::printf("PSNR: inf dB\n");
  else
    std::printf("PSNR: %.2f dB\n", 10.0 * std::log10(255.0 * 255.0 / mse));
  const bool pass = withinShare >= kPassShare;
  std::printf("%s\n", pass ? "PASS" : "FAIL");
  return pass ? 0 : 1;
}
