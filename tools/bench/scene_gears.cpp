// pineda-demo's gears, timed: the same scene code, drawn at the bench's size.
#include "bench_scene.h"
#include "demo/scene.h"

namespace pineda::bench {
namespace {

class Gears final : public BenchScene {
 public:
  Gears(int width, int height) : gears_(demo::createGears(width, height)) {}
  void draw(int frame) override { gears_->draw(frame); }
  long trianglesPerFrame() const override { return demo::gearsTrianglesPerFrame(); }

 private:
  std::unique_ptr<demo::Scene> gears_;
};

}  // namespace

std::unique_ptr<BenchScene> createGears(int width, int height) { return std::make_unique<Gears>(width, height); }

}  // namespace pineda::bench
