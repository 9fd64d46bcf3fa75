#include "scene.h"

namespace pineda::demo {

const std::vector<SceneEntry>& allScenes() {
  static const std::vector<SceneEntry> scenes = {
      {"triangles", createTriangles}, {"cube", createCube},   {"textured", createTextured},
      {"gears", createGears},         {"blend", createBlend}, {"lines_points", createLinesPoints},
      {"lit_fog", createLitFog},      {"smooth", createSmooth},
      {"es1_fixed", createEs1Fixed, true},
  };
  return scenes;
}

}  // namespace pineda::demo
