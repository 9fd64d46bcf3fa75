#pragma once
// Per-channel comparison of two RGBA8 images of the same size.
#include "png_io.h"

namespace pineda::tools {

struct ImageDifference {
  int maxDiff = 0;          // largest difference of any channel of any pixel
  double within1Share = 0;  // pixels whose every channel differs by at most 1
  double within8Share = 0;  // ... by at most 8
  double differShare = 0;   // pixels with any channel differing
  double psnr = 0;          // dB over all four channels; +infinity when identical
};

// `diff`, when given, receives a picture of where they differ: equal pixels as a dimmed grey
// copy of `a`, pixels off by 1 dark yellow, larger differences red (brighter when larger).
ImageDifference compareImages(const Image& a, const Image& b, Image* diff = nullptr);

}  // namespace pineda::tools
