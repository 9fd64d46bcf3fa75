// The scene of scene_data.h through desktop GL 1.5's float and double entry points.
#include <GL/gl.h>

#include "tests/es1/scene_data.h"

namespace pineda::es1_test {
namespace {

void float4(const double* v, GLfloat* out) {
  for (int i = 0; i < 4; ++i) out[i] = static_cast<GLfloat>(v[i]);
}

}  // namespace

std::vector<uint8_t> render_gl15_scene() {
  constexpr int kCount = sizeof(kSceneVertices) / sizeof(kSceneVertices[0]);
  GLfloat positions[kCount][3], normals[kCount][3], colors[kCount][4], texcoords[kCount][2];
  for (int i = 0; i < kCount; ++i) {
    const SceneVertex& v = kSceneVertices[i];
    for (int c = 0; c < 3; ++c) positions[i][c] = GLfloat(v.position[c]), normals[i][c] = GLfloat(v.normal[c]);
    float4(v.color, colors[i]);
    texcoords[i][0] = GLfloat(v.texcoord[0]);
    texcoords[i][1] = GLfloat(v.texcoord[1]);
  }
  GLfloat c4[4];
  glViewport(0, 0, kSceneSize, kSceneSize);
  float4(kSceneClearColor, c4);
  glClearColor(c4[0], c4[1], c4[2], c4[3]);
  glClearDepth(1);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthRange(0, 1);

  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-1, 1, -1, 1, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glTranslatef(GLfloat(kSceneTranslate[0]), GLfloat(kSceneTranslate[1]), GLfloat(kSceneTranslate[2]));
  glRotatef(GLfloat(kSceneRotate), 0, 0, 1);

  glEnable(GL_LIGHTING);
  glEnable(GL_LIGHT0);
  glEnable(GL_NORMALIZE);
  glEnable(GL_COLOR_MATERIAL);
  float4(kSceneLightDirection, c4);
  glLightfv(GL_LIGHT0, GL_POSITION, c4);
  float4(kSceneLightDiffuse, c4);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, c4);
  float4(kSceneAmbient, c4);
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, c4);

  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0);
  glFogf(GL_FOG_END, GLfloat(kSceneFogEnd));
  float4(kSceneFogColor, c4);
  glFogfv(GL_FOG_COLOR, c4);

  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, kSceneTexels);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_TEXTURE_2D);

  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glEnableClientState(GL_TEXTURE_COORD_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, positions);
  glNormalPointer(GL_FLOAT, 0, normals);
  glColorPointer(4, GL_FLOAT, 0, colors);
  glTexCoordPointer(2, GL_FLOAT, 0, texcoords);
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(GLfloat(kScenePolygonOffset[0]), GLfloat(kScenePolygonOffset[1]));
  glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_BYTE, kSceneTriangleIndices);

  std::vector<uint8_t> pixels(kSceneSize * kSceneSize * 4);
  glReadPixels(0, 0, kSceneSize, kSceneSize, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glDeleteTextures(1, &texture);
  return pixels;
}

}  // namespace pineda::es1_test
