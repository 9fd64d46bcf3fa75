// Streaming textures, as video players, emulators and SDL's renderer draw: every frame two
// 512x512 RGBA8 textures get new contents by glTexSubImage2D (one as GL_RGBA
// GL_UNSIGNED_BYTE, one as GL_BGRA GL_UNSIGNED_INT_8_8_8_8_REV) and each is drawn over half
// of the window, nearest-filtered.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

constexpr int kSize = 512;

class TextureUpload final : public BenchScene {
 public:
  TextureUpload(int, int) : texels_(std::size_t(kSize) * kSize) {
    glGenTextures(2, textures_);
    for (GLuint texture : textures_) {
      glBindTexture(GL_TEXTURE_2D, texture);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT);
    for (int i = 0; i < 2; ++i) {
      fill(frame * 2 + i);
      glBindTexture(GL_TEXTURE_2D, textures_[i]);
      if (i == 0) glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, texels_.data());
      else glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, kSize, kSize, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, texels_.data());
      const float x0 = i == 0 ? -1.0f : 0.0f, x1 = x0 + 1.0f;
      glBegin(GL_QUADS);
      glTexCoord2f(0, 0);
      glVertex2f(x0, -1);
      glTexCoord2f(1, 0);
      glVertex2f(x1, -1);
      glTexCoord2f(1, 1);
      glVertex2f(x1, 1);
      glTexCoord2f(0, 1);
      glVertex2f(x0, 1);
      glEnd();
    }
  }

  long trianglesPerFrame() const override { return 4; }

 private:
  // A moving pattern, as a decoded video frame would be new every frame.
  void fill(int step) {
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x)
        texels_[std::size_t(y) * kSize + x] = std::uint32_t((x + step) ^ (y * 3)) * 0x01030507u | 0xff000000u;
  }

  GLuint textures_[2] = {};
  std::vector<std::uint32_t> texels_;
};

}  // namespace

std::unique_ptr<BenchScene> createTextureUpload(int width, int height) {
  return std::make_unique<TextureUpload>(width, height);
}

}  // namespace pineda::bench
