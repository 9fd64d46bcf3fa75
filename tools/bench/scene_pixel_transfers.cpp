// The pixel paths other than the colour-byte ones read_pixels, draw_pixels and texture_upload
// cover, as tools, test harnesses, scientific viewers and GLUT programs take them, once each
// per frame: glGetTexImage of a 512x512 RGBA8 texture as bytes, glReadPixels of the frame's
// depth as GL_UNSIGNED_INT and as GL_FLOAT, of its stencil as bytes and of its colour as
// GL_FLOAT, glCopyPixels of the lower half onto the upper, glDrawPixels of a quarter-size
// GL_FLOAT image, and 1200 glBitmap glyphs of 8x13 (a screen of text).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

constexpr int kTextureSize = 512;

class PixelTransfers final : public BenchScene {
 public:
  PixelTransfers(int width, int height)
      : width_(width), height_(height), readback_(std::size_t(width) * height * 16),
        floats_(std::size_t(width / 4) * (height / 4) * 4) {
    std::vector<std::uint32_t> texels(std::size_t(kTextureSize) * kTextureSize);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = std::uint32_t(i * 2654435761u);
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kTextureSize, kTextureSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    for (std::size_t i = 0; i < floats_.size(); ++i) floats_[i] = float(i % 97) / 96.0f;
    for (int k = 0; k < 13; ++k) glyph_[k] = std::uint8_t(0x5a ^ (k * 37));
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glClearColor(0.2f, 0.4f, 0.6f, 1.0f);
    glClearStencil(3);
  }

  void draw(int frame) override {
    glClearDepth(0.25 + 0.5 * (frame % 2));
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback_.data());
    glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, readback_.data());
    glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, readback_.data());
    glReadPixels(0, 0, width_, height_, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, readback_.data());
    glWindowPos2i(width_ / 8, height_ / 8);
    glDrawPixels(width_ / 4, height_ / 4, GL_RGBA, GL_FLOAT, floats_.data());
    glColor3f(1.0f, 1.0f, 0.0f);
    for (int line = 0; line < 10; ++line) {
      glWindowPos2i(0, line * 15);
      for (int c = 0; c < 120; ++c) glBitmap(8, 13, 0.0f, 0.0f, 8.0f, 0.0f, glyph_);
    }
    glWindowPos2i(0, height_ / 2);
    glCopyPixels(0, 0, width_, height_ / 2, GL_COLOR);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_FLOAT, readback_.data());
  }

  long trianglesPerFrame() const override { return 0; }
  bool drawsWithStencil() const override { return true; }

 private:
  int width_, height_;
  std::vector<std::uint8_t> readback_;
  std::vector<float> floats_;
  std::uint8_t glyph_[13] = {};
};

}  // namespace

std::unique_ptr<BenchScene> createPixelTransfers(int width, int height) {
  return std::make_unique<PixelTransfers>(width, height);
}

}  // namespace pineda::bench
