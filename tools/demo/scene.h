#pragma once
// A demo scene: GL 1.1 calls (and ARB_multitexture where a scene says so), or the OpenGL 2.1,
// ES 1.1 or ES 2.0 ones of the context its entry asks for. Each scene runs in a fresh context,
// so it sets up everything it needs in its constructor and assumes GL's initial state.
#include <memory>
#include <string_view>
#include <vector>

#include "egl_session.h"

namespace pineda::demo {

class Scene {
 public:
  virtual ~Scene() = default;
  // Draws frame `frame`; animation depends only on the frame index.
  virtual void draw(int frame) = 0;
};

struct SceneEntry {
  std::string_view name;
  std::unique_ptr<Scene> (*create)(int width, int height);
  tools::ContextApi api = tools::ContextApi::GL11;  // the context the scene runs in
};

const std::vector<SceneEntry>& allScenes();

std::unique_ptr<Scene> createTriangles(int width, int height);
std::unique_ptr<Scene> createCube(int width, int height);
std::unique_ptr<Scene> createTextured(int width, int height);
std::unique_ptr<Scene> createGears(int width, int height);
int gearsTrianglesPerFrame();  // for pineda-bench, which draws the same gears
std::unique_ptr<Scene> createBlend(int width, int height);
std::unique_ptr<Scene> createLinesPoints(int width, int height);
std::unique_ptr<Scene> createLitFog(int width, int height);
std::unique_ptr<Scene> createEs1Fixed(int width, int height);
std::unique_ptr<Scene> createSmooth(int width, int height);
std::unique_ptr<Scene> createEs2FboLit(int width, int height);
std::unique_ptr<Scene> createGl21Shaded(int width, int height);
std::unique_ptr<Scene> createMsaa(int width, int height);

}  // namespace pineda::demo
