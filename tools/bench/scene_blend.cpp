// Alpha-blended fill: full-screen smooth-shaded quads with translucent corner colours,
// SRC_ALPHA / ONE_MINUS_SRC_ALPHA, no depth test, alpha writes masked.
#include <GL/gl.h>

#include <cmath>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

constexpr int kLayers = 32;

class Blend final : public BenchScene {
 public:
  Blend(int, int) {
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glShadeModel(GL_SMOOTH);
  }

  void draw(int frame) override {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);  // alpha stays 1, so the PNG shows the colours
    glBegin(GL_QUADS);
    for (int i = 0; i < kLayers; ++i) {
      const float phase = 0.4f * float(i) + 0.05f * float(frame);
      const auto corner = [&](float x, float y, float offset) {
        const float a = phase + offset;
        glColor4f(0.5f + 0.5f * std::sin(a), 0.5f + 0.5f * std::sin(a + 2.1f), 0.5f + 0.5f * std::sin(a + 4.2f),
                  0.05f + 0.25f * (0.5f + 0.5f * std::cos(a * 1.3f)));
        glVertex2f(x, y);
      };
      corner(-1.0f, -1.0f, 0.0f);
      corner(1.0f, -1.0f, 1.5f);
      corner(1.0f, 1.0f, 3.0f);
      corner(-1.0f, 1.0f, 4.5f);
    }
    glEnd();
  }

  long trianglesPerFrame() const override { return 2L * kLayers; }
};

}  // namespace

std::unique_ptr<BenchScene> createBlend(int width, int height) { return std::make_unique<Blend>(width, height); }

}  // namespace pineda::bench
