// glDrawPixels, as image viewers, emulators and old visualisation programs put pictures on the
// screen: every frame a window-sized GL_RGBA GL_UNSIGNED_BYTE image covers the window, then a
// quarter-size GL_RGB image is drawn over its middle at pixel zoom 2 (unpack alignment 1). Two
// prepared images alternate, so that the frame measures the driver and not the scene.
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

class DrawPixels final : public BenchScene {
 public:
  DrawPixels(int width, int height)
      : width_(width), height_(height), small_width_(width / 4), small_height_(height / 4) {
    for (int k = 0; k < 2; ++k) {
      full_[k].resize(std::size_t(width_) * height_ * 4);
      small_[k].resize(std::size_t(small_width_) * small_height_ * 3);
      fill(full_[k], width_, height_, 4, k);
      fill(small_[k], small_width_, small_height_, 3, k + 7);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT);
    const int k = frame % 2;
    glPixelZoom(1.0f, 1.0f);
    glRasterPos2f(-1.0f, -1.0f);
    glDrawPixels(width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, full_[k].data());
    glPixelZoom(2.0f, 2.0f);
    glRasterPos2f(-0.25f, -0.25f);
    glDrawPixels(small_width_, small_height_, GL_RGB, GL_UNSIGNED_BYTE, small_[k].data());
  }

  long trianglesPerFrame() const override { return 0; }

 private:
  static void fill(std::vector<std::uint8_t>& image, int width, int height, int components, int seed) {
    std::size_t i = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        for (int c = 0; c < components; ++c) image[i++] = std::uint8_t((x * (c + 1) + y * (3 - c)) ^ (seed * 37 + c));
  }

  int width_, height_, small_width_, small_height_;
  std::vector<std::uint8_t> full_[2], small_[2];
};

}  // namespace

std::unique_ptr<BenchScene> createDrawPixels(int width, int height) {
  return std::make_unique<DrawPixels>(width, height);
}

}  // namespace pineda::bench
