// Alpha blending, alpha test, a stencil-masked region and a scissored region.
#include <GL/gl.h>

#include <cmath>

#include "scene.h"

namespace pineda::demo {
namespace {

void quad(float x0, float y0, float x1, float y1) {
  glVertex2f(x0, y0); glVertex2f(x1, y0); glVertex2f(x1, y1); glVertex2f(x0, y1);
}

class Blend final : public Scene {
 public:
  Blend(int width, int height) : width_(width), height_(height) {
    glClearColor(0.25f, 0.3f, 0.35f, 1.0f);
    glClearStencil(0);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glLoadIdentity();
    drawScissored(frame);
    drawStencilled(frame);
    drawAlphaTested();
    drawBlended(frame);
  }

 private:
  // The lower-left corner: a scissored clear, then a triangle cut by the same scissor box.
  void drawScissored(int frame) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(width_ / 20, height_ / 20, width_ * 2 / 5, height_ * 2 / 5);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glClearColor(0.25f, 0.3f, 0.35f, 1.0f);
    float shift = 0.01f * (frame % 10);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.6f, 0.0f); glVertex2f(0.0f + shift, 0.0f);
    glColor3f(0.0f, 0.6f, 1.0f); glVertex2f(0.6f + shift, 0.1f);
    glColor3f(1.0f, 1.0f, 1.0f); glVertex2f(0.2f + shift, 0.6f);
    glEnd();
    glDisable(GL_SCISSOR_TEST);
  }

  // The upper-right corner: a disc written to stencil only, then stripes drawn where it is.
  void drawStencilled(int frame) {
    glEnable(GL_STENCIL_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glBegin(GL_TRIANGLE_FAN);
    glVertex2f(0.75f, 0.75f);
    for (int i = 0; i <= 32; ++i) {
      float angle = 2.0f * 3.14159265f * i / 32;
      glVertex2f(0.75f + 0.2f * std::cos(angle), 0.75f + 0.2f * std::sin(angle));
    }
    glEnd();

    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glBegin(GL_QUADS);
    float offset = 0.005f * (frame % 8);
    for (int i = 0; i < 12; ++i) {
      float y = 0.5f + offset + i * 0.04f;
      glColor3f(i % 2 ? 1.0f : 0.2f, 0.8f, i % 2 ? 0.2f : 1.0f);
      quad(0.5f, y, 1.0f, y + 0.04f);
    }
    glEnd();
    glDisable(GL_STENCIL_TEST);
  }

  // The lower-right corner: alpha rises left to right; only alpha > 0.4 survives.
  void drawAlphaTested() {
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.4f);
    glBegin(GL_QUADS);
    glColor4f(0.9f, 0.9f, 0.2f, 0.0f); glVertex2f(0.55f, 0.05f);
    glColor4f(0.9f, 0.2f, 0.9f, 1.0f); glVertex2f(0.95f, 0.05f);
    glColor4f(0.9f, 0.2f, 0.9f, 1.0f); glVertex2f(0.95f, 0.4f);
    glColor4f(0.9f, 0.9f, 0.2f, 0.0f); glVertex2f(0.55f, 0.4f);
    glEnd();
    glDisable(GL_ALPHA_TEST);
  }

  // The upper-left and centre: translucent quads over each other and over the other parts.
  void drawBlended(int frame) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    const float colours[3][4] = {{1.0f, 0.1f, 0.1f, 0.5f}, {0.1f, 1.0f, 0.1f, 0.6f}, {0.1f, 0.2f, 1.0f, 0.7f}};
    for (int i = 0; i < 3; ++i) {
      glPushMatrix();
      glTranslatef(0.3f + 0.1f * i, 0.7f - 0.08f * i, 0.0f);
      glRotatef(frame * 2.0f + 15.0f * i, 0.0f, 0.0f, 1.0f);
      glColor4fv(colours[i]);
      glBegin(GL_QUADS);
      quad(-0.17f, -0.17f, 0.17f, 0.17f);
      glEnd();
      glPopMatrix();
    }
    glDisable(GL_BLEND);
  }

  int width_;
  int height_;
};

}  // namespace

std::unique_ptr<Scene> createBlend(int width, int height) { return std::make_unique<Blend>(width, height); }

}  // namespace pineda::demo
