#include "driver/frame_capture.h"

#include <png.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

namespace pineda::driver {
namespace {

const char* capture_dir() {
  static const char* dir = [] {
    const char* d = std::getenv("PINEDA_CAPTURE");
    return d && *d ? d : nullptr;
  }();
  return dir;
}

// Frames are numbered for the whole process, whichever API presents them.
int next_frame_number() {
  static std::atomic<int> next{0};
  return next.fetch_add(1);
}

void report_once(const std::string& message) {
  static std::atomic<bool> reported{false};
  if (!reported.exchange(true)) std::fprintf(stderr, "pineda: PINEDA_CAPTURE: %s\n", message.c_str());
}

// Tight RGB rows, top row first (what is shown; alpha is not part of a window's picture).
std::vector<uint8_t> top_down_rgb(const raster::ColorBuffer& color, int width, int height) {
  std::vector<uint8_t> rgb(static_cast<size_t>(width) * height * 3);
  const bool bgra = color.format == raster::ColorFormat::BGRA8;
  uint8_t* out = rgb.data();
  for (int y = height - 1; y >= 0; --y) {
    const uint8_t* p = color.base + color.stride * y;
    for (int x = 0; x < width; ++x, p += 4, out += 3) {
      out[0] = p[bgra ? 2 : 0];
      out[1] = p[1];
      out[2] = p[bgra ? 0 : 2];
    }
  }
  return rgb;
}

}  // namespace

void capture_frame(const raster::ColorBuffer& color, int width, int height) {
  const char* dir = capture_dir();
  if (!dir || !color.base || width <= 0 || height <= 0) return;
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  char name[32];
  std::snprintf(name, sizeof name, "frame-%05d.png", next_frame_number());
  const std::string path = (std::filesystem::path(dir) / name).string();
  std::vector<uint8_t> rgb = top_down_rgb(color, width, height);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32>(width);
  png.height = static_cast<png_uint_32>(height);
  png.format = PNG_FORMAT_RGB;
  if (!png_image_write_to_file(&png, path.c_str(), 0, rgb.data(), 0, nullptr))
    report_once(path + ": " + png.message);
}

}  // namespace pineda::driver
