// A lit tessellated torus around a sphere: smooth shading, per-vertex normals from client
// arrays, glDrawElements, GL_LIGHTING with a white directional light and a coloured positional
// light with attenuation, specular highlights, back faces culled.
#include <GL/gl.h>

#include <cmath>
#include <vector>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

constexpr float kPi = 3.14159265f;

struct Mesh {
  std::vector<float> positions, normals;
  std::vector<GLuint> indices;
};

// A (columns x rows)-cell grid over the surface `at(u, v, position, normal)`, u and v in [0, 1],
// wrapping in both directions; triangles wound counter-clockwise seen from outside.
template <typename Surface>
Mesh tessellate(int columns, int rows, Surface at) {
  Mesh mesh;
  for (int j = 0; j <= rows; ++j)
    for (int i = 0; i <= columns; ++i) {
      float p[3], n[3];
      at(float(i) / columns, float(j) / rows, p, n);
      mesh.positions.insert(mesh.positions.end(), p, p + 3);
      mesh.normals.insert(mesh.normals.end(), n, n + 3);
    }
  const GLuint side = GLuint(columns + 1);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const GLuint v = GLuint(j) * side + GLuint(i);
      mesh.indices.insert(mesh.indices.end(), {v, v + 1, v + side + 1, v, v + side + 1, v + side});
    }
  return mesh;
}

Mesh torus(int columns, int rows, float major, float minor) {
  return tessellate(columns, rows, [&](float u, float v, float* p, float* n) {
    const float a = 2 * kPi * u, b = 2 * kPi * v;
    n[0] = std::cos(a) * std::cos(b), n[1] = std::sin(a) * std::cos(b), n[2] = std::sin(b);
    const float ring = major + minor * std::cos(b);
    p[0] = ring * std::cos(a), p[1] = ring * std::sin(a), p[2] = minor * std::sin(b);
  });
}

Mesh sphere(int columns, int rows, float radius) {
  return tessellate(columns, rows, [&](float u, float v, float* p, float* n) {
    const float a = 2 * kPi * u, b = kPi * (v - 0.5f);
    n[0] = std::cos(a) * std::cos(b), n[1] = std::sin(a) * std::cos(b), n[2] = std::sin(b);
    for (int c = 0; c < 3; ++c) p[c] = radius * n[c];
  });
}

void drawMesh(const Mesh& mesh) {
  glVertexPointer(3, GL_FLOAT, 0, mesh.positions.data());
  glNormalPointer(GL_FLOAT, 0, mesh.normals.data());
  glDrawElements(GL_TRIANGLES, GLsizei(mesh.indices.size()), GL_UNSIGNED_INT, mesh.indices.data());
}

class LitMesh final : public BenchScene {
 public:
  LitMesh(int width, int height) : torus_(torus(256, 128, 1.0f, 0.4f)), sphere_(sphere(128, 64, 0.5f)) {
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glShadeModel(GL_SMOOTH);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    const GLfloat white[4] = {0.8f, 0.8f, 0.8f, 1.0f};
    const GLfloat warm[4] = {0.9f, 0.5f, 0.2f, 1.0f};
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, warm);
    glLightfv(GL_LIGHT1, GL_SPECULAR, warm);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.15f);
    const GLfloat specular[4] = {0.6f, 0.6f, 0.6f, 1.0f};
    glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glMatrixMode(GL_PROJECTION);
    const double aspect = double(width) / height;
    glFrustum(-0.1 * aspect, 0.1 * aspect, -0.1, 0.1, 0.2, 20.0);
    glMatrixMode(GL_MODELVIEW);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    // Lights are placed in eye space (identity modelview), so they stay put while the mesh turns.
    const GLfloat direction[4] = {-0.5f, 1.0f, 1.0f, 0.0f};
    const GLfloat position[4] = {2.0f, -1.0f, -1.5f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, direction);
    glLightfv(GL_LIGHT1, GL_POSITION, position);
    glTranslatef(0.0f, 0.0f, -3.2f);
    glRotatef(60.0f + 3.0f * float(frame), 1.0f, 0.3f, 0.0f);
    const GLfloat teal[4] = {0.1f, 0.6f, 0.7f, 1.0f}, ivory[4] = {0.9f, 0.85f, 0.7f, 1.0f};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, teal);
    drawMesh(torus_);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, ivory);
    drawMesh(sphere_);
  }

  long trianglesPerFrame() const override { return long(torus_.indices.size() + sphere_.indices.size()) / 3; }

 private:
  Mesh torus_, sphere_;
};

}  // namespace

std::unique_ptr<BenchScene> createLitMesh(int width, int height) { return std::make_unique<LitMesh>(width, height); }

}  // namespace pineda::bench
