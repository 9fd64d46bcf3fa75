// A blur as programs make one: a smooth-shaded scene is drawn, then four times a frame the
// framebuffer is copied into a texture (glCopyTexSubImage2D) and drawn back over itself,
// shifted by a pixel and blended at half strength. The texture is the next power of two
// above the window (GL 1.x textures need not be that size, but GL 1.1 programs do it).
#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

constexpr int kPasses = 4;
constexpr int kBaseQuads = 8;

int nextPowerOfTwo(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

class CopyBlur final : public BenchScene {
 public:
  CopyBlur(int width, int height) : width_(width), height_(height), size_(nextPowerOfTwo(std::max(width, height))) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, size_, size_, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, width, 0, height, -1, 1);
    glMatrixMode(GL_MODELVIEW);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT);
    drawBase(frame);
    const float s = float(width_) / float(size_), t = float(height_) / float(size_);
    for (int pass = 0; pass < kPasses; ++pass) {
      glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, width_, height_);
      const float dx = (pass % 2 ? -1.0f : 1.0f), dy = (pass / 2 ? -1.0f : 1.0f);
      glEnable(GL_TEXTURE_2D);
      glEnable(GL_BLEND);
      glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
      glBegin(GL_QUADS);
      glTexCoord2f(0, 0), glVertex2f(dx, dy);
      glTexCoord2f(s, 0), glVertex2f(float(width_) + dx, dy);
      glTexCoord2f(s, t), glVertex2f(float(width_) + dx, float(height_) + dy);
      glTexCoord2f(0, t), glVertex2f(dx, float(height_) + dy);
      glEnd();
      glDisable(GL_BLEND);
      glDisable(GL_TEXTURE_2D);
    }
  }

  long trianglesPerFrame() const override { return 2L * (kBaseQuads + kPasses); }

 private:
  void drawBase(int frame) {
    glBegin(GL_QUADS);
    for (int i = 0; i < kBaseQuads; ++i) {
      const float a = 0.7f * float(i) + 0.1f * float(frame);
      const float cx = float(width_) * (0.5f + 0.35f * std::cos(a)), cy = float(height_) * (0.5f + 0.35f * std::sin(a));
      const float r = 0.12f * float(std::min(width_, height_));
      glColor3f(1.0f, 0.3f, 0.2f), glVertex2f(cx - r, cy - r);
      glColor3f(0.2f, 1.0f, 0.3f), glVertex2f(cx + r, cy - r);
      glColor3f(0.2f, 0.3f, 1.0f), glVertex2f(cx + r, cy + r);
      glColor3f(1.0f, 1.0f, 0.3f), glVertex2f(cx - r, cy + r);
    }
    glEnd();
  }

  int width_, height_, size_;
  GLuint texture_ = 0;
};

}  // namespace

std::unique_ptr<BenchScene> createCopyBlur(int width, int height) {
  return std::make_unique<CopyBlur>(width, height);
}

}  // namespace pineda::bench
