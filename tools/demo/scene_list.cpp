#include "scene.h"

namespace pineda::demo {

const std::vector<SceneEntry>& allScenes() {
  static const std::vector<SceneEntry> scenes = {
      {"triangles", createTriangles}, {"cube", createCube},   {"textured", createTextured},
      {"gears", createGears},         {"blend", createBlend}, {"lines_points", createLinesPoints},
      {"lit_fog", createLitFog},      {"smooth", createSmooth},
      {"es1_fixed", createEs1Fixed, tools::ContextApi::ES11},
      {"es2_fbo_lit", createEs2FboLit, tools::ContextApi::ES20},
      {"gl21_shaded", createGl21Shaded, tools::ContextApi::GL21},
      {"msaa", createMsaa, tools::ContextApi::GL21},
  };
  return scenes;
}

}  // namespace pineda::demo
