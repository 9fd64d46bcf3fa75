// glReadPixels of the whole frame, as screenshot tools, video capture and test harnesses read
// it: a smooth-shaded frame is drawn, then read back twice, as GL_RGBA and as GL_RGB (pack
// alignment 4), both GL_UNSIGNED_BYTE, into client memory.
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

class ReadPixels final : public BenchScene {
 public:
  ReadPixels(int width, int height)
      : width_(width), height_(height), rgba_(std::size_t(width) * height * 4),
        rgb_(std::size_t((width * 3 + 3) / 4 * 4) * height) {
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT);
    const float shift = float(frame % 16) / 16.0f;
    glBegin(GL_TRIANGLE_STRIP);
    glColor3f(1.0f, shift, 0.0f);
    glVertex2f(-1.0f, -1.0f);
    glColor3f(0.0f, 1.0f, shift);
    glVertex2f(1.0f, -1.0f);
    glColor3f(shift, 0.0f, 1.0f);
    glVertex2f(-1.0f, 1.0f);
    glColor3f(1.0f, 1.0f, 1.0f - shift);
    glVertex2f(1.0f, 1.0f);
    glEnd();
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, rgba_.data());
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, rgb_.data());
  }

  long trianglesPerFrame() const override { return 2; }

 private:
  int width_, height_;
  std::vector<std::uint8_t> rgba_, rgb_;
};

}  // namespace

std::unique_ptr<BenchScene> createReadPixels(int width, int height) {
  return std::make_unique<ReadPixels>(width, height);
}

}  // namespace pineda::bench
