// A perspective checkerboard floor (trilinear mipmapping, REPEAT, MODULATE) and a
// NEAREST-filtered quad showing a small texture magnified.
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "box_filter.h"
#include "scene.h"

namespace pineda::demo {
namespace {


Texels checkerboard(int size, int check) {
  Texels texels(std::size_t(size) * size * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      bool light = ((x / check) + (y / check)) % 2 == 0;
      std::uint8_t* texel = &texels[(std::size_t(y) * size + x) * 4];
      texel[0] = light ? 240 : 40;
      texel[1] = light ? 230 : 60;
      texel[2] = light ? 200 : 110;
      texel[3] = 255;
    }
  return texels;
}

class Textured final : public Scene {
 public:
  Textured(int width, int height) {
    glClearColor(0.5f, 0.7f, 0.9f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(2, textures_);

    glBindTexture(GL_TEXTURE_2D, textures_[0]);
    int size = 64;
    Texels level = checkerboard(size, 8);
    for (int lod = 0; size >= 1; ++lod, size /= 2) {
      glTexImage2D(GL_TEXTURE_2D, lod, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, level.data());
      if (size > 1) level = halve(level, size, 4);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);

    glBindTexture(GL_TEXTURE_2D, textures_[1]);
    Texels small = checkerboard(4, 1);
    small[0] = 255, small[1] = 40, small[2] = 40;  // a red corner texel shows orientation
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, small.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glMatrixMode(GL_PROJECTION);
    double aspect = double(width) / height;
    glFrustum(-0.1 * aspect, 0.1 * aspect, -0.1, 0.1, 0.2, 100.0);
    glMatrixMode(GL_MODELVIEW);
  }

  ~Textured() override { glDeleteTextures(2, textures_); }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, -1.0f, 0.0f);
    glRotatef(frame * 1.5f, 0.0f, 1.0f, 0.0f);

    glBindTexture(GL_TEXTURE_2D, textures_[0]);
    glBegin(GL_QUADS);  // the floor, tinted warmer towards the horizon
    glColor3f(1.0f, 1.0f, 1.0f); glTexCoord2f(0.0f, 0.0f);   glVertex3f(-40.0f, 0.0f, 40.0f);
    glColor3f(1.0f, 1.0f, 1.0f); glTexCoord2f(20.0f, 0.0f);  glVertex3f(40.0f, 0.0f, 40.0f);
    glColor3f(1.0f, 0.8f, 0.6f); glTexCoord2f(20.0f, 20.0f); glVertex3f(40.0f, 0.0f, -40.0f);
    glColor3f(1.0f, 0.8f, 0.6f); glTexCoord2f(0.0f, 20.0f);  glVertex3f(-40.0f, 0.0f, -40.0f);
    glEnd();

    glLoadIdentity();
    glBindTexture(GL_TEXTURE_2D, textures_[1]);
    glBegin(GL_QUADS);  // a magnified 4x4 texture standing above the floor
    glColor3f(1.0f, 1.0f, 1.0f);
    glTexCoord2f(0.0f, 0.0f); glVertex3f(-0.9f, 0.1f, -3.0f);
    glTexCoord2f(1.0f, 0.0f); glVertex3f(0.9f, 0.1f, -3.0f);
    glTexCoord2f(1.0f, 1.0f); glVertex3f(0.9f, 1.3f, -3.0f);
    glTexCoord2f(0.0f, 1.0f); glVertex3f(-0.9f, 1.3f, -3.0f);
    glEnd();
  }

 private:
  GLuint textures_[2] = {};
};

}  // namespace

std::unique_ptr<Scene> createTextured(int width, int height) { return std::make_unique<Textured>(width, height); }

}  // namespace pineda::demo
