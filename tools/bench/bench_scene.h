#pragma once
// A benchmark scene: GL 1.1 calls (the glsl_* scenes: GL 2.1 and GLSL 1.20). Each scene runs
// in a fresh context, so it sets up everything it needs in its constructor and assumes GL's initial state. The bench counts
// rasterized fragments with the stencil buffer, so a scene that uses it says so (and gets no count).
#include <memory>
#include <string_view>
#include <vector>

namespace pineda::bench {

class BenchScene {
 public:
  virtual ~BenchScene() = default;
  // Draws frame `frame` (clear included); animation depends only on the frame index.
  virtual void draw(int frame) = 0;
  // Triangles submitted per frame, quads and strips counted as the triangles they make.
  virtual long trianglesPerFrame() const = 0;
  // Draw calls per frame, for the scenes that time the calls themselves (0: not reported).
  virtual long drawCallsPerFrame() const { return 0; }
  virtual bool drawsWithStencil() const { return false; }
};

struct BenchSceneEntry {
  std::string_view name;
  std::string_view description;
  std::unique_ptr<BenchScene> (*create)(int width, int height);
};

const std::vector<BenchSceneEntry>& allBenchScenes();
const BenchSceneEntry* findBenchScene(std::string_view name);

std::unique_ptr<BenchScene> createOverdraw(int width, int height);
std::unique_ptr<BenchScene> createBlend(int width, int height);
std::unique_ptr<BenchScene> createSmallTris(int width, int height);
std::unique_ptr<BenchScene> createTextured(int width, int height);
std::unique_ptr<BenchScene> createLitMesh(int width, int height);
std::unique_ptr<BenchScene> createGears(int width, int height);
std::unique_ptr<BenchScene> createStateChanges(int width, int height);
std::unique_ptr<BenchScene> createSmallDraws(int width, int height);
std::unique_ptr<BenchScene> createCopyBlur(int width, int height);
std::unique_ptr<BenchScene> createReadPixels(int width, int height);
std::unique_ptr<BenchScene> createDrawPixels(int width, int height);
std::unique_ptr<BenchScene> createPixelTransfers(int width, int height);
std::unique_ptr<BenchScene> createTextureUpload(int width, int height);
std::unique_ptr<BenchScene> createWireframe(int width, int height);
std::unique_ptr<BenchScene> createStencilReflection(int width, int height);
std::unique_ptr<BenchScene> createGlslLit(int width, int height);
std::unique_ptr<BenchScene> createGlslSkinned(int width, int height);
std::unique_ptr<BenchScene> createGlslProcedural(int width, int height);
std::unique_ptr<BenchScene> createGlslSprites(int width, int height);
std::unique_ptr<BenchScene> createGlslRenderToTexture(int width, int height);
std::unique_ptr<BenchScene> createGlslManyDraws(int width, int height);
std::unique_ptr<BenchScene> createGlslSmallDraws(int width, int height);
std::unique_ptr<BenchScene> createGlslMsaa(int width, int height);

}  // namespace pineda::bench
