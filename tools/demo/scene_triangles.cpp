// Smooth-shaded overlapping triangles at different depths, a triangle fan and a strip.
#include <GL/gl.h>

#include <cmath>

#include "scene.h"

namespace pineda::demo {
namespace {

class Triangles final : public Scene {
 public:
  Triangles() {
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glRotatef(frame * 3.0f, 0.0f, 0.0f, 1.0f);

    // Two triangles that pierce each other: depth decides per pixel which one shows.
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f); glVertex3f(-0.9f, 0.1f, -0.5f);
    glColor3f(0.0f, 1.0f, 0.0f); glVertex3f(-0.1f, 0.1f, 0.5f);
    glColor3f(0.0f, 0.0f, 1.0f); glVertex3f(-0.5f, 0.9f, -0.5f);
    glColor3f(1.0f, 1.0f, 0.0f); glVertex3f(-0.9f, 0.7f, 0.4f);
    glColor3f(0.0f, 1.0f, 1.0f); glVertex3f(-0.1f, 0.7f, 0.4f);
    glColor3f(1.0f, 0.0f, 1.0f); glVertex3f(-0.5f, 0.2f, -0.6f);
    glEnd();

    // A fan approximating a disc, its centre raised towards the viewer.
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(0.5f, 0.5f, 0.3f);
    const int segments = 12;
    for (int i = 0; i <= segments; ++i) {
      float angle = 2.0f * 3.14159265f * float(i) / segments;
      glColor3f(0.5f + 0.5f * std::cos(angle), 0.5f + 0.5f * std::sin(angle), 0.5f);
      glVertex3f(0.5f + 0.38f * std::cos(angle), 0.5f + 0.38f * std::sin(angle), -0.3f);
    }
    glEnd();

    // A wavy strip across the bottom half, passing through the fan's depth range.
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i <= 10; ++i) {
      float x = -0.9f + 1.8f * float(i) / 10;
      float wave = 0.1f * std::sin(float(i));
      glColor3f(float(i) / 10, 0.3f, 1.0f - float(i) / 10);
      glVertex3f(x, -0.2f + wave, 0.8f - 0.16f * i);
      glColor3f(0.2f, float(i) / 10, 0.4f);
      glVertex3f(x, -0.8f + wave, 0.8f - 0.16f * i);
    }
    glEnd();
  }
};

}  // namespace

std::unique_ptr<Scene> createTriangles(int, int) { return std::make_unique<Triangles>(); }

}  // namespace pineda::demo
