// Antialiased lines of widths 1, 1.5 and 2.5, antialiased points of sizes 1 to 8 and a
// triangle with GL_POLYGON_SMOOTH, blended with SRC_ALPHA, ONE_MINUS_SRC_ALPHA over grey.
#include <GL/gl.h>

#include <cmath>

#include "scene.h"

namespace pineda::demo {
namespace {

constexpr float kPi = 3.14159265f;

class Smooth final : public Scene {
 public:
  Smooth(int width, int height) : width_(width), height_(height) { glClearColor(0.2f, 0.2f, 0.25f, 1.0f); }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, width_, 0.0, height_, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    drawLines(frame);
    drawPoints(frame);
    drawPolygon(frame);
    glDisable(GL_BLEND);
  }

 private:
  // The top half: a fan of lines per width.
  void drawLines(int frame) {
    glEnable(GL_LINE_SMOOTH);
    const float widths[3] = {1.0f, 1.5f, 2.5f};
    for (int k = 0; k < 3; ++k) {
      glLineWidth(widths[k]);
      const float cx = width_ * (0.17f + 0.33f * k), cy = height_ * 0.72f, r = height_ * 0.22f;
      glBegin(GL_LINES);
      for (int i = 0; i < 16; ++i) {
        const float angle = 2 * kPi * i / 16 + frame * 0.013f;
        glColor4f(1.0f, 0.4f + 0.6f * i / 16, 0.2f, 1.0f);
        glVertex2f(cx + 0.1f * r * std::cos(angle), cy + 0.1f * r * std::sin(angle));
        glVertex2f(cx + r * std::cos(angle), cy + r * std::sin(angle));
      }
      glEnd();
    }
    glLineWidth(1.0f);
    glDisable(GL_LINE_SMOOTH);
  }

  // Below: a row of points per size, 1 to 8, at varied sub-pixel positions.
  void drawPoints(int frame) {
    glEnable(GL_POINT_SMOOTH);
    for (int size = 1; size <= 8; ++size) {
      glPointSize(float(size));
      glBegin(GL_POINTS);
      for (int i = 0; i < 12; ++i) {
        glColor4f(0.3f + 0.05f * i, 1.0f, 0.6f, 1.0f);
        glVertex2f(width_ * (0.05f + 0.075f * i) + 0.37f * i + 0.1f * frame, height_ * (0.42f - 0.04f * size) + 0.23f * i);
      }
      glEnd();
    }
    glPointSize(1.0f);
    glDisable(GL_POINT_SMOOTH);
  }

  // A thin triangle on the right: what GL_POLYGON_SMOOTH does to edges.
  void drawPolygon(int frame) {
    glEnable(GL_POLYGON_SMOOTH);
    glColor4f(0.4f, 0.7f, 1.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    glVertex2f(width_ * 0.93f, height_ * 0.05f);
    glVertex2f(width_ * 0.98f + frame * 0.1f, height_ * 0.45f);
    glVertex2f(width_ * 0.90f, height_ * 0.40f);
    glEnd();
    glDisable(GL_POLYGON_SMOOTH);
  }

  int width_;
  int height_;
};

}  // namespace

std::unique_ptr<Scene> createSmooth(int width, int height) { return std::make_unique<Smooth>(width, height); }

}  // namespace pineda::demo
