// The scene of scene_data.h through OpenGL ES 1.1's GLfixed entry points and GL_FIXED arrays.
#include <GLES/gl.h>

#include "tests/es1/scene_data.h"

namespace pineda::es1_test {
namespace {

constexpr GLfixed X(double v) { return static_cast<GLfixed>(v * 65536.0); }

void fixed4(const double* v, GLfixed* out) {
  for (int i = 0; i < 4; ++i) out[i] = X(v[i]);
}

}  // namespace

std::vector<uint8_t> render_es1_fixed_scene() {
  constexpr int kCount = sizeof(kSceneVertices) / sizeof(kSceneVertices[0]);
  GLfixed positions[kCount][3], normals[kCount][3], colors[kCount][4], texcoords[kCount][2];
  for (int i = 0; i < kCount; ++i) {
    const SceneVertex& v = kSceneVertices[i];
    for (int c = 0; c < 3; ++c) positions[i][c] = X(v.position[c]), normals[i][c] = X(v.normal[c]);
    fixed4(v.color, colors[i]);
    texcoords[i][0] = X(v.texcoord[0]);
    texcoords[i][1] = X(v.texcoord[1]);
  }
  GLfixed c4[4];
  glViewport(0, 0, kSceneSize, kSceneSize);
  fixed4(kSceneClearColor, c4);
  glClearColorx(c4[0], c4[1], c4[2], c4[3]);
  glClearDepthx(X(1));
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthRangex(X(0), X(1));

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrthox(X(-1), X(1), X(-1), X(1), X(-1), X(1));
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatex(X(kSceneTranslate[0]), X(kSceneTranslate[1]), X(kSceneTranslate[2]));
  glRotatex(X(kSceneRotate), 0, 0, X(1));

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  fixed4(kSceneLightDirection, c4);
  glLightxv(GL_LIGHT0, GL_POSITION, c4);
  fixed4(kSceneLightDiffuse, c4);
  glLightxv(GL_LIGHT0, GL_DIFFUSE, c4);
  fixed4(kSceneAmbient, c4);
  glLightModelxv(GL_LIGHT_MODEL_AMBIENT, c4);

  glEnable(GL_FOG);
  glFogx(GL_FOG_MODE, GL_LINEAR);
  glFogx(GL_FOG_START, 0);
  glFogx(GL_FOG_END, X(kSceneFogEnd));
  fixed4(kSceneFogColor, c4);
  glFogxv(GL_FOG_COLOR, c4);

  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, kSceneTexels);
  glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameterx(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvx(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);

  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glVertexPointer(3, GL_FIXED, 0, positions);
  glNormalPointer(GL_FIXED, 0, normals);
  glColorPointer(4, GL_FIXED, 0, colors);
  glTexCoordPointer(2, GL_FIXED, 0, texcoords);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffsetx(X(kScenePolygonOffset[0]), X(kScenePolygonOffset[1]));
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, kSceneTriangleIndices);

  std::vector<uint8_t> pixels(kSceneSize * kSceneSize * 4);
  glReadPixels(0, 0, kSceneSize, kSceneSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glDeleteTextures(1, &texture);
  return pixels;
}

}  // namespace pineda::es1_test
