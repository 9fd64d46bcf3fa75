// Half a million small triangles: a 500x500-cell wavy grid covering the screen (about 1.6
// pixels per triangle at 1024x768), drawn with one glDrawElements call from client arrays.
#include <GL/gl.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

constexpr int kCells = 500;

class SmallTris final : public BenchScene {
 public:
  SmallTris(int, int) {
    constexpr int side = kCells + 1;
    positions_.reserve(std::size_t(side) * side * 3);
    colours_.reserve(std::size_t(side) * side * 4);
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        const float x = -1.02f + 2.04f * float(i) / kCells, y = -1.02f + 2.04f * float(j) / kCells;
        const float z = 0.3f * std::sin(9.0f * x) * std::cos(7.0f * y);
        positions_.insert(positions_.end(), {x, y, z});
        colours_.insert(colours_.end(), {std::uint8_t(128 + 127 * x / 1.02f), std::uint8_t(128 + 127 * y / 1.02f),
                                         std::uint8_t(128 + 400 * z), 255});
      }
    indices_.reserve(std::size_t(kCells) * kCells * 6);
    for (int j = 0; j < kCells; ++j)
      for (int i = 0; i < kCells; ++i) {
        const GLuint v = GLuint(j * side + i);
        indices_.insert(indices_.end(), {v, v + 1, v + side + 1, v, v + side + 1, v + side});
      }
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, positions_.data());
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, colours_.data());
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0007f * float(frame % 20), 0.0f, 0.0f);  // moves edges across pixel centres
    glDrawElements(GL_TRIANGLES, GLsizei(indices_.size()), GL_UNSIGNED_INT, indices_.data());
  }

  long trianglesPerFrame() const override { return 2L * kCells * kCells; }

 private:
  std::vector<float> positions_;
  std::vector<std::uint8_t> colours_;
  std::vector<GLuint> indices_;
};

}  // namespace

std::unique_ptr<BenchScene> createSmallTris(int width, int height) {
  return std::make_unique<SmallTris>(width, height);
}

}  // namespace pineda::bench
