// Depth-test overdraw: full-screen quads on tilted planes, so neighbouring layers cross and the
// picture shows which layer won where. The first pass goes front-to-back (almost every fragment
// fails the depth test), the second, after a depth clear, back-to-front (every fragment passes).
#include <GL/gl.h>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

constexpr int kLayersPerPass = 32;

class Overdraw final : public BenchScene {
 public:
  Overdraw(int, int) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const float shift = 0.01f * float(frame % 16);
    for (int i = 0; i < kLayersPerPass; ++i) layer(i, shift, false);
    glClear(GL_DEPTH_BUFFER_BIT);
    for (int i = kLayersPerPass - 1; i >= 0; --i) layer(i, shift, true);
  }

  long trianglesPerFrame() const override { return 2L * 2 * kLayersPerPass; }

 private:
  // Layer i lies around depth -0.8 + 1.6 i / (n - 1) (nearer for smaller i), tilted so that it
  // crosses its neighbours but stays inside the clip volume.
  static void layer(int i, float shift, bool secondPass) {
    const float base = -0.8f + 1.6f * float(i) / float(kLayersPerPass - 1);
    const float tiltX = (i % 3 - 1) * 0.1f, tiltY = (i % 2 ? 0.08f : -0.08f);
    const auto z = [&](float x, float y) { return base + tiltX * (x + shift) + tiltY * y; };
    const int tint = secondPass ? 0 : 100;
    glColor3ub(GLubyte(55 + (i * 97 + tint) % 200), GLubyte(55 + (i * 57 + tint) % 200),
               GLubyte(55 + (i * 29 + tint) % 200));
    glBegin(GL_QUADS);
    glVertex3f(-1.0f, -1.0f, z(-1.0f, -1.0f));
    glVertex3f(1.0f, -1.0f, z(1.0f, -1.0f));
    glVertex3f(1.0f, 1.0f, z(1.0f, 1.0f));
    glVertex3f(-1.0f, 1.0f, z(-1.0f, 1.0f));
    glEnd();
  }
};

}  // namespace

std::unique_ptr<BenchScene> createOverdraw(int width, int height) {
  return std::make_unique<Overdraw>(width, height);
}

}  // namespace pineda::bench
