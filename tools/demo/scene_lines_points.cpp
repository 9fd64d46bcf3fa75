// Lines of widths 1 and 3, line strips and loops, points of sizes 1, 4 and 9, and a
// height-field mesh drawn with glPolygonMode(GL_LINE).
#include <GL/gl.h>

#include <cmath>

#include "scene.h"

namespace pineda::demo {
namespace {

constexpr float kPi = 3.14159265f;

class LinesPoints final : public Scene {
 public:
  LinesPoints(int width, int height) : width_(width), height_(height) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    drawLines(frame);
    drawPoints(frame);
    drawMesh(frame);
  }

 private:
  // The top half: a fan of thin and thick lines, a strip and a loop.
  void drawLines(int frame) {
    for (float width : {1.0f, 3.0f}) {
      glLineWidth(width);
      float cx = width == 1.0f ? 0.17f : 0.5f;
      glBegin(GL_LINES);
      for (int i = 0; i < 12; ++i) {
        float angle = kPi * i / 12 + frame * 0.02f;
        glColor3f(1.0f, float(i) / 12, 0.2f);
        glVertex2f(cx, 0.77f);
        glVertex2f(cx + 0.15f * std::cos(angle), 0.77f + 0.2f * std::sin(angle));
      }
      glEnd();
    }
    glLineWidth(1.0f);

    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= 20; ++i) {
      glColor3f(0.2f, 1.0f, float(i) / 20);
      glVertex2f(0.68f + 0.015f * i, 0.62f + 0.08f * std::sin(i * 0.9f + frame * 0.1f));
    }
    glEnd();

    glLineWidth(3.0f);
    glBegin(GL_LINE_LOOP);
    for (int i = 0; i < 5; ++i) {  // a pentagram
      float angle = kPi / 2 + 4 * kPi * i / 5;
      glColor3f(0.4f, 0.6f, 1.0f);
      glVertex2f(0.83f + 0.1f * std::cos(angle), 0.85f + 0.1f * std::sin(angle));
    }
    glEnd();
    glLineWidth(1.0f);
  }

  // The middle band: three rows of points, one per size.
  void drawPoints(int frame) {
    const float sizes[3] = {1.0f, 4.0f, 9.0f};
    for (int row = 0; row < 3; ++row) {
      glPointSize(sizes[row]);
      glBegin(GL_POINTS);
      for (int i = 0; i < 16; ++i) {
        float x = 0.04f + 0.058f * i + 0.003f * row;
        float y = 0.43f + 0.05f * row + 0.02f * std::sin(i + frame * 0.2f);
        glColor3f(float(i) / 16, 1.0f - float(i) / 16, 0.5f + 0.25f * row);
        glVertex2f(x, y);
      }
      glEnd();
    }
    glPointSize(1.0f);
  }

  // The bottom: a rippled grid in perspective, its quads drawn as outlines.
  void drawMesh(int frame) {
    const int meshHeight = height_ * 3 / 8;
    glViewport(0, 0, width_, meshHeight);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    double aspect = double(width_) / meshHeight;
    glFrustum(-0.1 * aspect, 0.1 * aspect, -0.1, 0.1, 0.2, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -0.3f, -2.2f);
    glRotatef(35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(frame * 1.5f, 0.0f, 1.0f, 0.0f);

    glEnable(GL_DEPTH_TEST);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    const int cells = 14;
    auto height = [&](int i, int j) {
      float x = float(i) / cells - 0.5f, z = float(j) / cells - 0.5f;
      return 0.12f * std::cos(9.0f * std::sqrt(x * x + z * z));
    };
    for (int j = 0; j < cells; ++j) {
      glBegin(GL_QUAD_STRIP);
      for (int i = 0; i <= cells; ++i) {
        for (int row : {j, j + 1}) {
          float y = height(i, row);
          glColor3f(0.3f + 2.5f * y, 0.7f, 1.0f - 2.5f * y);
          glVertex3f(2.0f * i / cells - 1.0f, y, 2.0f * row / cells - 1.0f);
        }
      }
      glEnd();
    }
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_DEPTH_TEST);
    glViewport(0, 0, width_, height_);
  }

  int width_;
  int height_;
};

}  // namespace

std::unique_ptr<Scene> createLinesPoints(int width, int height) {
  return std::make_unique<LinesPoints>(width, height);
}

}  // namespace pineda::demo
