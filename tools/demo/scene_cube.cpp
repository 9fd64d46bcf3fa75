// A rotating colour cube in perspective, depth tested, back faces culled.
#include <GL/gl.h>

#include "scene.h"

namespace pineda::demo {
namespace {

// Corner i has colour (i & 1, i >> 1 & 1, i >> 2 & 1) and the same position bits mapped to ±1.
constexpr int kFaces[6][4] = {
    {0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5},
};

class Cube final : public Scene {
 public:
  Cube(int width, int height) {
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glMatrixMode(GL_PROJECTION);
    double aspect = double(width) / height;
    glFrustum(-0.5 * aspect, 0.5 * aspect, -0.5, 0.5, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -4.0f);
    glRotatef(30.0f + frame * 2.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(40.0f + frame * 3.0f, 0.0f, 1.0f, 0.0f);
    glRotatef(10.0f, 0.0f, 0.0f, 1.0f);
    glBegin(GL_QUADS);
    for (const auto& face : kFaces) {
      for (int corner : face) {
        float r = float(corner & 1), g = float(corner >> 1 & 1), b = float(corner >> 2 & 1);
        glColor3f(r, g, b);
        glVertex3f(r * 2 - 1, g * 2 - 1, b * 2 - 1);
      }
    }
    glEnd();
  }
};

}  // namespace

std::unique_ptr<Scene> createCube(int width, int height) { return std::make_unique<Cube>(width, height); }

}  // namespace pineda::demo
