// What wire-frame and point-cloud programs draw: a 64x64-cell height field as GL_LINE_STRIPs
// (8k one-pixel lines) and the same vertices again as GL_POINTS of size 2, depth-tested,
// flat colour per strip, rotating with the frame index.
#include <GL/gl.h>

#include <cmath>
#include <vector>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

constexpr int kCells = 64;

float height(float x, float z) { return 0.25f * std::sin(3.0f * x) * std::cos(2.0f * z); }

class Wireframe final : public BenchScene {
 public:
  Wireframe(int width, int height) {
    glClearColor(0.0f, 0.0f, 0.05f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glPointSize(2.0f);
    glMatrixMode(GL_PROJECTION);
    const float aspect = float(width) / float(height);
    glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    for (int j = 0; j <= kCells; ++j)
      for (int i = 0; i <= kCells; ++i) {
        const float x = 2.0f * float(i) / kCells - 1.0f, z = 2.0f * float(j) / kCells - 1.0f;
        grid_.insert(grid_.end(), {x, ::pineda::bench::height(x, z), z});
      }
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, -0.2f, -2.6f);
    glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(2.0f * float(frame), 0.0f, 1.0f, 0.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, grid_.data());
    const int side = kCells + 1;
    for (int j = 0; j <= kCells; ++j) {  // rows along x
      glColor3f(0.2f + 0.8f * float(j) / kCells, 0.9f, 0.3f);
      glDrawArrays(GL_LINE_STRIP, j * side, side);
    }
    for (int i = 0; i <= kCells; ++i) {  // columns along z
      glColor3f(0.3f, 0.6f, 0.2f + 0.8f * float(i) / kCells);
      glBegin(GL_LINE_STRIP);
      for (int j = 0; j <= kCells; ++j) glArrayElement(j * side + i);
      glEnd();
    }
    glColor3f(1.0f, 1.0f, 1.0f);
    glDrawArrays(GL_POINTS, 0, side * side);
    glDisableClientState(GL_VERTEX_ARRAY);
  }

  long trianglesPerFrame() const override { return 0; }  // lines and points only

 private:
  std::vector<float> grid_;
};

}  // namespace

std::unique_ptr<BenchScene> createWireframe(int width, int height) {
  return std::make_unique<Wireframe>(width, height);
}

}  // namespace pineda::bench
