// Three meshing gears in the manner of glxgears: quads and quad strips in display lists,
// one directional light, flat-shaded faces, smooth-shaded bores, GL_NORMALIZE.
#include <GL/gl.h>

#include <cmath>

#include "scene.h"

namespace pineda::demo {
namespace {

constexpr float kPi = 3.14159265f;

struct GearShape {
  float inner;   // bore radius
  float outer;   // pitch radius
  float width;   // thickness along z
  int teeth;
  float depth;   // tooth height
};

void vertexAt(float radius, float angle, float z) {
  glVertex3f(radius * std::cos(angle), radius * std::sin(angle), z);
}

// One face of the gear (the z = +w/2 side when front, else z = -w/2), wound counter-clockwise
// as seen from outside.
void gearFace(const GearShape& g, bool front) {
  const float r0 = g.inner, r1 = g.outer - g.depth / 2, r2 = g.outer + g.depth / 2;
  const float step = 2 * kPi / g.teeth, quarter = step / 4;
  const float z = front ? g.width / 2 : -g.width / 2;
  glNormal3f(0.0f, 0.0f, front ? 1.0f : -1.0f);

  // The ring, sampled where each tooth starts and ends so tooth bases meet its outline.
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= g.teeth; ++i) {
    for (float angle : {i * step, i * step + 3 * quarter}) {
      if (i == g.teeth && angle > i * step) break;
      vertexAt(front ? r0 : r1, angle, z);
      vertexAt(front ? r1 : r0, angle, z);
    }
  }
  glEnd();

  glBegin(GL_QUADS);
  for (int i = 0; i < g.teeth; ++i) {
    float a = i * step;
    if (front) {
      vertexAt(r1, a, z); vertexAt(r2, a + quarter, z); vertexAt(r2, a + 2 * quarter, z); vertexAt(r1, a + 3 * quarter, z);
    } else {
      vertexAt(r1, a + 3 * quarter, z); vertexAt(r2, a + 2 * quarter, z); vertexAt(r2, a + quarter, z); vertexAt(r1, a, z);
    }
  }
  glEnd();
}

// The outline's side walls, each a quad with its own outward normal.
void gearRim(const GearShape& g) {
  const float r1 = g.outer - g.depth / 2, r2 = g.outer + g.depth / 2;
  const float step = 2 * kPi / g.teeth, quarter = step / 4, h = g.width / 2;
  glBegin(GL_QUADS);
  for (int i = 0; i < g.teeth; ++i) {
    float a = i * step;
    const float outline[5][2] = {{r1, a}, {r2, a + quarter}, {r2, a + 2 * quarter}, {r1, a + 3 * quarter}, {r1, a + step}};
    for (int s = 0; s < 4; ++s) {
      float px = outline[s][0] * std::cos(outline[s][1]), py = outline[s][0] * std::sin(outline[s][1]);
      float qx = outline[s + 1][0] * std::cos(outline[s + 1][1]), qy = outline[s + 1][0] * std::sin(outline[s + 1][1]);
      glNormal3f(qy - py, px - qx, 0.0f);  // GL_NORMALIZE makes it unit length
      glVertex3f(px, py, h); glVertex3f(px, py, -h); glVertex3f(qx, qy, -h); glVertex3f(qx, qy, h);
    }
  }
  glEnd();
}

void gearBore(const GearShape& g) {
  const int segments = g.teeth * 2;
  glShadeModel(GL_SMOOTH);
  glBegin(GL_QUAD_STRIP);
  for (int i = 0; i <= segments; ++i) {
    float angle = 2 * kPi * i / segments;
    glNormal3f(-std::cos(angle), -std::sin(angle), 0.0f);
    vertexAt(g.inner, angle, -g.width / 2);
    vertexAt(g.inner, angle, g.width / 2);
  }
  glEnd();
  glShadeModel(GL_FLAT);
}

constexpr GearShape kGears[3] = {{1.0f, 4.0f, 1.0f, 20, 0.7f}, {0.5f, 2.0f, 2.0f, 10, 0.7f}, {1.3f, 2.0f, 0.5f, 10, 0.7f}};

GLuint buildGear(const GearShape& shape, const GLfloat colour[4]) {
  GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colour);
  glShadeModel(GL_FLAT);
  gearFace(shape, true);
  gearFace(shape, false);
  gearRim(shape);
  gearBore(shape);
  glEndList();
  return list;
}

class Gears final : public Scene {
 public:
  Gears(int width, int height) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    const GLfloat lightDirection[4] = {5.0f, 5.0f, 10.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, lightDirection);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_CULL_FACE);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_NORMALIZE);

    const GLfloat colours[3][4] = {{0.8f, 0.1f, 0.0f, 1.0f}, {0.0f, 0.8f, 0.2f, 1.0f}, {0.2f, 0.2f, 1.0f, 1.0f}};
    for (int i = 0; i < 3; ++i) lists_[i] = buildGear(kGears[i], colours[i]);

    glMatrixMode(GL_PROJECTION);
    double aspect = double(height) / width;
    glFrustum(-1.0, 1.0, -aspect, aspect, 5.0, 60.0);
    glMatrixMode(GL_MODELVIEW);
  }

  ~Gears() override {
    for (GLuint list : lists_) glDeleteLists(list, 1);
  }

  void draw(int frame) override {
    const float angle = 10.0f + frame * 2.0f;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(1.0f, 0.0f, -40.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
    const struct { float x, y, turn, phase; } placements[3] = {
        {-3.0f, -2.0f, 1.0f, 0.0f}, {3.1f, -2.0f, -2.0f, -9.0f}, {-3.1f, 4.2f, -2.0f, -25.0f}};
    for (int i = 0; i < 3; ++i) {
      glPushMatrix();
      glTranslatef(placements[i].x, placements[i].y, 0.0f);
      glRotatef(placements[i].turn * angle + placements[i].phase, 0.0f, 0.0f, 1.0f);
      glCallList(lists_[i]);
      glPopMatrix();
    }
  }

 private:
  GLuint lists_[3] = {};
};

}  // namespace

int gearsTrianglesPerFrame() {
  // Per tooth: each face's ring 4 and tooth 2, the rim 8, the bore 4.
  int triangles = 0;
  for (const GearShape& gear : kGears) triangles += 24 * gear.teeth;
  return triangles;
}

std::unique_ptr<Scene> createGears(int width, int height) { return std::make_unique<Gears>(width, height); }

}  // namespace pineda::demo
