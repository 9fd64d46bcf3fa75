// Perspective-textured planes: a corridor (floor, ceiling, two walls, each split into 16
// segments along its depth) and an end wall, 256x256 textures with full mipmap chains,
// GL_LINEAR_MIPMAP_LINEAR, REPEAT, MODULATE. The camera moves forward with the frame index.
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

using Texels = std::vector<std::uint8_t>;  // RGBA8

constexpr int kTextureSize = 256;
constexpr int kSegments = 16;
constexpr float kLength = 40.0f;  // corridor depth

// Bricks (kind 0) or a tiled floor (kind 1), with fine detail so that mipmapping shows.
Texels pattern(int kind) {
  Texels texels(std::size_t(kTextureSize) * kTextureSize * 4);
  for (int y = 0; y < kTextureSize; ++y)
    for (int x = 0; x < kTextureSize; ++x) {
      std::uint8_t* t = &texels[(std::size_t(y) * kTextureSize + x) * 4];
      int r, g, b;
      if (kind == 0) {
        const int row = y / 32, bx = (x + (row % 2) * 32) % 64;
        const bool mortar = y % 32 < 3 || bx < 3;
        const int grain = ((x * 7 + y * 13) % 17) * 3;
        r = mortar ? 200 : 150 + grain, g = mortar ? 200 : 60 + grain / 2, b = mortar ? 190 : 40;
      } else {
        const bool light = ((x / 32) + (y / 32)) % 2 == 0;
        const bool line = x % 32 == 0 || y % 32 == 0;
        r = line ? 20 : light ? 230 : 60, g = line ? 20 : light ? 225 : 70, b = line ? 20 : light ? 210 : 120;
      }
      t[0] = std::uint8_t(r), t[1] = std::uint8_t(g), t[2] = std::uint8_t(b), t[3] = 255;
    }
  return texels;
}

Texels halve(const Texels& level, int size) {
  const int half = size / 2;
  Texels out(std::size_t(half) * half * 4);
  for (int y = 0; y < half; ++y)
    for (int x = 0; x < half; ++x)
      for (int c = 0; c < 4; ++c) {
        auto at = [&](int sx, int sy) { return int(level[(std::size_t(sy) * size + sx) * 4 + c]); };
        const int sum = at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1);
        out[(std::size_t(y) * half + x) * 4 + c] = std::uint8_t((sum + 2) / 4);
      }
  return out;
}

void uploadMipmapped(const Texels& base) {
  Texels level = base;
  for (int lod = 0, size = kTextureSize; size >= 1; ++lod, size /= 2) {
    glTexImage2D(GL_TEXTURE_2D, lod, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, level.data());
    if (size > 1) level = halve(level, size);
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

class Textured final : public BenchScene {
 public:
  Textured(int width, int height) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(2, textures_);
    for (int i = 0; i < 2; ++i) {
      glBindTexture(GL_TEXTURE_2D, textures_[i]);
      uploadMipmapped(pattern(i));
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glMatrixMode(GL_PROJECTION);
    const double aspect = double(width) / height;
    glFrustum(-0.1 * aspect, 0.1 * aspect, -0.1, 0.1, 0.1, 100.0);
    glMatrixMode(GL_MODELVIEW);
  }

  ~Textured() override { glDeleteTextures(2, textures_); }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glRotatef(8.0f, 0.0f, 1.0f, 0.0f);  // look slightly to the side: walls at different slopes
    glTranslatef(0.0f, 0.0f, 0.1f * float(frame % 40));
    // Each plane: a fixed coordinate (axis 0 = x wall, 1 = y floor/ceiling) at `at`, the
    // other coordinate spanning [-1.5, 1.5]; texture repeats every 1.5 units.
    glBindTexture(GL_TEXTURE_2D, textures_[0]);
    plane(0, -1.5f, 1.0f);
    plane(0, 1.5f, 0.85f);
    glBindTexture(GL_TEXTURE_2D, textures_[1]);
    plane(1, -1.0f, 1.0f);
    plane(1, 1.0f, 0.6f);
    glBindTexture(GL_TEXTURE_2D, textures_[0]);
    glBegin(GL_QUADS);  // the end wall
    glColor3f(0.7f, 0.7f, 0.9f);
    glTexCoord2f(0.0f, 0.0f); glVertex3f(-1.5f, -1.0f, -kLength);
    glTexCoord2f(2.0f, 0.0f); glVertex3f(1.5f, -1.0f, -kLength);
    glTexCoord2f(2.0f, 1.3f); glVertex3f(1.5f, 1.0f, -kLength);
    glTexCoord2f(0.0f, 1.3f); glVertex3f(-1.5f, 1.0f, -kLength);
    glEnd();
  }

  long trianglesPerFrame() const override { return 4L * kSegments * 2 + 2; }

 private:
  static void plane(int axis, float at, float brightness) {
    glColor3f(brightness, brightness, brightness);
    glBegin(GL_QUADS);
    for (int s = 0; s < kSegments; ++s) {
      const float z0 = 2.0f - (kLength + 2.0f) * float(s) / kSegments;
      const float z1 = 2.0f - (kLength + 2.0f) * float(s + 1) / kSegments;
      const float span = axis == 0 ? 1.0f : 1.5f;
      const auto vertex = [&](float across, float z) {
        glTexCoord2f((across + span) / 1.5f, -z / 1.5f);
        if (axis == 0)
          glVertex3f(at, across, z);
        else
          glVertex3f(across, at, z);
      };
      vertex(-span, z0); vertex(span, z0); vertex(span, z1); vertex(-span, z1);
    }
    glEnd();
  }

  GLuint textures_[2] = {};
};

}  // namespace

std::unique_ptr<BenchScene> createTextured(int width, int height) {
  return std::make_unique<Textured>(width, height);
}

}  // namespace pineda::bench
