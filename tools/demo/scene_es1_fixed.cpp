// OpenGL ES 1.1 (common profile) in fixed point: three lit, textured cubes in fog, every
// number passed as GLfixed (glFrustumx, glRotatex, glLightxv, glFogx...) and every array
// GL_FIXED, drawn with glDrawElements.
#include <GLES/gl.h>

#include "scene.h"

namespace pineda::demo {
namespace {

constexpr GLfixed X(double v) { return static_cast<GLfixed>(v * 65536.0); }

// Per face: normal, then four corners counter-clockwise seen from outside.
constexpr int kFaceNormals[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

class Es1Fixed final : public Scene {
 public:
  Es1Fixed(int width, int height) {
    buildCube();
    glClearColorx(X(0.55), X(0.6), X(0.7), X(1));
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glMatrixMode(GL_PROJECTION);
    const GLfixed aspect = X(double(width) / height);
    glFrustumx(-aspect / 2, aspect / 2, X(-0.5), X(0.5), X(1), X(20));
    glMatrixMode(GL_MODELVIEW);

    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    const GLfixed direction[] = {X(0.3), X(0.6), X(1), 0};
    const GLfixed diffuse[] = {X(0.9), X(0.85), X(0.8), X(1)};
    const GLfixed ambient[] = {X(0.25), X(0.25), X(0.3), X(1)};
    glLightxv(GL_LIGHT0, GL_POSITION, direction);
    glLightxv(GL_LIGHT0, GL_DIFFUSE, diffuse);
    glLightModelxv(GL_LIGHT_MODEL_AMBIENT, ambient);
    const GLfixed specular[] = {X(0.5), X(0.5), X(0.5), X(1)};
    glMaterialxv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialx(GL_FRONT_AND_BACK, GL_SHININESS, X(24));
    glLightxv(GL_LIGHT0, GL_SPECULAR, specular);

    glEnable(GL_FOG);
    glFogx(GL_FOG_MODE, GL_LINEAR);
    glFogx(GL_FOG_START, X(3));
    glFogx(GL_FOG_END, X(12));
    const GLfixed fog[] = {X(0.55), X(0.6), X(0.7), X(1)};
    glFogxv(GL_FOG_COLOR, fog);

    GLubyte texels[8 * 8 * 4];
    for (int i = 0; i < 64; ++i) {
      const bool light = ((i & 7) < 4) != (i / 8 < 4);
      texels[i * 4 + 0] = light ? 240 : 200;
      texels[i * 4 + 1] = light ? 200 : 90;
      texels[i * 4 + 2] = light ? 120 : 40;
      texels[i * 4 + 3] = 255;
    }
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);

    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(3, GL_FIXED, 0, positions_);
    glNormalPointer(GL_FIXED, 0, normals_);
    glTexCoordPointer(2, GL_FIXED, 0, texcoords_);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const GLfixed places[3][3] = {{X(-1.6), X(-0.4), X(-5)}, {X(0.4), X(0.5), X(-7)}, {X(1.9), X(-0.6), X(-10)}};
    for (int i = 0; i < 3; ++i) {
      glLoadIdentity();
      glTranslatex(places[i][0], places[i][1], places[i][2]);
      glRotatex(X(25 + 40 * i + 3 * frame), X(1), X(0.5), 0);
      glRotatex(X(15 * i + 2 * frame), 0, X(1), 0);
      glDrawElements(GL_TRIANGLES, 36, GL_UNSIGNED_BYTE, indices_);
    }
  }

 private:
  void buildCube() {
    for (int f = 0; f < 6; ++f) {
      const int* n = kFaceNormals[f];
      // u: the next axis after the normal's; v = n x u, so that u x v = n and the corners run
      // counter-clockwise seen from outside.
      const int axis = n[0] ? 0 : n[1] ? 1 : 2;
      int u[3] = {0, 0, 0};
      u[(axis + 1) % 3] = 1;
      const int v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2], n[0] * u[1] - n[1] * u[0]};
      const int corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (int c = 0; c < 4; ++c) {
        const int k = f * 4 + c;
        for (int a = 0; a < 3; ++a) {
          positions_[k][a] = X(n[a] + corners[c][0] * u[a] + corners[c][1] * v[a]) / 2;
          normals_[k][a] = X(n[a]);
        }
        texcoords_[k][0] = X(corners[c][0] > 0 ? 1 : 0);
        texcoords_[k][1] = X(corners[c][1] > 0 ? 1 : 0);
      }
      const int base = f * 4;
      const int quad[6] = {base, base + 1, base + 2, base, base + 2, base + 3};
      for (int i = 0; i < 6; ++i) indices_[f * 6 + i] = GLubyte(quad[i]);
    }
  }

  GLfixed positions_[24][3], normals_[24][3], texcoords_[24][2];
  GLubyte indices_[36];
  GLuint texture_ = 0;
};

}  // namespace

std::unique_ptr<Scene> createEs1Fixed(int width, int height) { return std::make_unique<Es1Fixed>(width, height); }

}  // namespace pineda::demo
