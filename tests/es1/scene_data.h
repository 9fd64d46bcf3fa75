// One lit, textured, fogged, depth-tested scene, as plain numbers that the OpenGL ES 1.1 code
// passes as GLfixed and the GL 1.5 code as float: all are multiples of 1/256, so both forms
// carry exactly the same values.
#pragma once
#include <cstdint>
#include <vector>

namespace pineda::es1_test {

inline constexpr int kSceneSize = 64;

struct SceneVertex {
  double position[3];
  double normal[3];
  double color[4];
  double texcoord[2];
};

// A quad (triangle strip, vertices 0-3) and a triangle through it (vertices 4-6, drawn with
// indices).
inline constexpr SceneVertex kSceneVertices[] = {
    {{-0.75, -0.75, 0.5}, {0, 0, 1}, {1, 0.5, 0.25, 1}, {0, 0}},
    {{0.75, -0.75, 0.5}, {0.25, 0, 1}, {0.5, 1, 0.25, 1}, {2, 0}},
    {{-0.75, 0.75, -0.25}, {0, 0.25, 1}, {0.25, 0.5, 1, 1}, {0, 2}},
    {{0.75, 0.75, -0.25}, {-0.25, -0.25, 1}, {1, 1, 1, 1}, {2, 2}},
    {{-0.5, -0.875, -0.5}, {0, 0, 1}, {1, 0, 0, 1}, {0.5, 0.5}},
    {{0.875, 0.125, 0.75}, {0, 0.5, 1}, {0, 1, 0, 1}, {1.5, 0.5}},
    {{-0.25, 0.875, 0.125}, {0.5, 0, 1}, {0, 0, 1, 1}, {0.5, 1.5}},
};
inline constexpr uint8_t kSceneTriangleIndices[] = {4, 5, 6};

// A 2x2 RGBA texture, repeated twice across the quad.
inline constexpr uint8_t kSceneTexels[16] = {255, 255, 255, 255, 128, 128, 255, 255,
                                             255, 128, 128, 255, 192, 255, 192, 255};

inline constexpr double kSceneClearColor[4] = {0.25, 0.5, 0.75, 1};
inline constexpr double kSceneLightDirection[4] = {0.25, 0.5, 1, 0};
inline constexpr double kSceneLightDiffuse[4] = {0.75, 0.75, 0.75, 1};
inline constexpr double kSceneAmbient[4] = {0.25, 0.25, 0.25, 1};
inline constexpr double kSceneFogColor[4] = {0.5, 0.5, 0.5, 1};
inline constexpr double kSceneFogEnd = 2.5;
inline constexpr double kSceneTranslate[3] = {0.125, -0.0625, 0};
inline constexpr double kSceneRotate = 30;  // degrees about z
inline constexpr double kScenePolygonOffset[2] = {1, 2};

// The scene drawn by the context current on the calling thread, read back as RGBA8 rows.
std::vector<uint8_t> render_es1_fixed_scene();  // OpenGL ES 1.1, GLfixed calls and arrays
std::vector<uint8_t> render_gl15_scene();        // GL 1.5, float and double calls

}  // namespace pineda::es1_test
