// pineda-imgdiff A.png B.png [--diff OUT.png]: per-channel comparison of two images.
// Exit status: 0 when at least 99.9% of pixels are within 1/255 on every channel,
// 1 when they are not, 2 on error.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "image_compare.h"
#include "png_io.h"

using pineda::tools::Image;

namespace {

constexpr double kPassShare = 0.999;

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
  const pineda::tools::ImageDifference stats =
      pineda::tools::compareImages(a, b, diffPath.empty() ? nullptr : &diff);
  if (!diffPath.empty() && !pineda::tools::writePng(diffPath, diff, error)) {
    std::fprintf(stderr, "pineda-imgdiff: %s\n", error.c_str());
    return 2;
  }

  std::printf("max channel difference: %d\n", stats.maxDiff);
  std::printf("pixels within 1/255: %.4f%%\n", 100.0 * stats.within1Share);
  std::printf("pixels within 8/255: %.4f%%\n", 100.0 * stats.within8Share);
  std::printf("pixels differing: %.4f%%\n", 100.0 * stats.differShare);
  if (std::isinf(stats.psnr))
    std::printf("PSNR: inf dB\n");
  else
    std::printf("PSNR: %.2f dB\n", stats.psnr);
  const bool pass = stats.within1Share >= kPassShare;
  std::printf("%s\n", pass ? "PASS" : "FAIL");
  return pass ? 0 : 1;
}
