// A planar reflection as programs draw one with the stencil buffer (the classic mirror): the
// floor is written into the stencil buffer, the lit scene is drawn mirrored where the stencil
// is set, the floor is blended over it, then the scene is drawn upright.
#include <GL/gl.h>

#include <cmath>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

constexpr int kCubes = 24;

void cube() {  // unit cube, normals per face
  static const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  glBegin(GL_QUADS);
  for (const auto& f : n) {
    glNormal3fv(f);
    const int a = f[0] != 0 ? 0 : f[1] != 0 ? 1 : 2, b = (a + 1) % 3, c = (a + 2) % 3;
    const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k) {
      const int kk = (f[a] > 0) ? k : 3 - k;
      float v[3];
      v[a] = 0.5f * f[a], v[b] = 0.5f * corners[kk][0], v[c] = 0.5f * corners[kk][1];
      glVertex3fv(v);
    }
  }
  glEnd();
}

class StencilReflection final : public BenchScene {
 public:
  StencilReflection(int width, int height) {
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClearStencil(0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    glMatrixMode(GL_PROJECTION);
    const float aspect = float(width) / float(height);
    glFrustum(-0.6 * aspect, 0.6 * aspect, -0.6, 0.6, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, -1.0f, -6.0f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(float(frame), 0.0f, 1.0f, 0.0f);
    const GLfloat light[4] = {2.0f, 5.0f, 3.0f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    // The floor into the stencil buffer only.
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    floor();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    // The mirrored scene where the floor is.
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glPushMatrix();
    glScalef(1.0f, -1.0f, 1.0f);
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glCullFace(GL_FRONT);
    scene(frame);
    glCullFace(GL_BACK);
    glPopMatrix();
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glDisable(GL_STENCIL_TEST);
    // The floor blended over the reflection, then the scene itself.
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.6f, 0.6f, 0.7f, 0.6f);
    floor();
    glDisable(GL_BLEND);
    scene(frame);
  }

  long trianglesPerFrame() const override { return 2L * (2 + 2 * kCubes * 6); }
  bool drawsWithStencil() const override { return true; }

 private:
  static void floor() {
    glDisable(GL_LIGHTING);
    glBegin(GL_QUADS);
    glVertex3f(-3.0f, 0.0f, 3.0f), glVertex3f(3.0f, 0.0f, 3.0f);
    glVertex3f(3.0f, 0.0f, -3.0f), glVertex3f(-3.0f, 0.0f, -3.0f);
    glEnd();
  }

  static void scene(int frame) {
    glEnable(GL_LIGHTING);
    for (int i = 0; i < kCubes; ++i) {
      const float a = 6.2831853f * float(i) / kCubes + 0.02f * float(frame);
      glPushMatrix();
      glTranslatef(2.0f * std::cos(a), 0.6f + 0.3f * std::sin(3.0f * a), 2.0f * std::sin(a));
      glRotatef(40.0f * float(i) + float(frame), 0.3f, 1.0f, 0.2f);
      glScalef(0.5f, 0.5f, 0.5f);
      glColor3f(0.5f + 0.5f * std::cos(a), 0.5f + 0.5f * std::sin(a), 0.6f);
      cube();
      glPopMatrix();
    }
    glDisable(GL_LIGHTING);
  }
};

}  // namespace

std::unique_ptr<BenchScene> createStencilReflection(int width, int height) {
  return std::make_unique<StencilReflection>(width, height);
}

}  // namespace pineda::bench
