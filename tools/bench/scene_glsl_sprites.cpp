// GLSL 1.20, particles: 6000 alpha-blended textured sprites (quads of 12 to 44 pixels, in one
// glDrawArrays from client arrays), each fragment sampling a soft round 64x64 RGBA8 texture,
// discarding where its alpha is below 0.05 and tinting by a per-sprite colour. Sprites move
// with the frame index.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "bench_scene.h"
#include "demo/shader_program.h"

namespace pineda::bench {
namespace {

constexpr int kSprites = 6000;
constexpr int kTextureSize = 64;

const char* const kVertex = R"(#version 120
attribute vec2 position;
attribute vec2 corner;
attribute vec4 tint;
uniform vec2 pixel_size;
varying vec2 v_texcoord;
varying vec4 v_tint;
void main() {
  v_texcoord = corner * 0.5 + 0.5;
  v_tint = tint;
  gl_Position = vec4(position + corner * tint.a * 22.0 * pixel_size, 0.0, 1.0);
})";

const char* const kFragment = R"(#version 120
uniform sampler2D sprite_map;
varying vec2 v_texcoord;
varying vec4 v_tint;
void main() {
  vec4 texel = texture2D(sprite_map, v_texcoord);
  if (texel.a < 0.05) discard;
  gl_FragColor = vec4(texel.rgb * v_tint.rgb, texel.a * 0.8);
})";

// A deterministic pseudo-random sequence in [0, 1).
float next_random(std::uint32_t& state) {
  state = state * 1664525u + 1013904223u;
  return float(state >> 8) / float(1u << 24);
}

class GlslSprites final : public BenchScene {
 public:
  GlslSprites(int width, int height) : width_(width), height_(height) {
    std::vector<std::uint8_t> texels(kTextureSize * kTextureSize * 4);
    for (int y = 0; y < kTextureSize; ++y)
      for (int x = 0; x < kTextureSize; ++x) {
        const float dx = (float(x) + 0.5f) / (kTextureSize / 2) - 1.0f, dy = (float(y) + 0.5f) / (kTextureSize / 2) - 1.0f;
        const float falloff = std::fmax(0.0f, 1.0f - std::sqrt(dx * dx + dy * dy));
        std::uint8_t* t = &texels[(y * kTextureSize + x) * 4];
        t[0] = std::uint8_t(255.0f * (0.6f + 0.4f * falloff));
        t[1] = std::uint8_t(255.0f * (0.5f + 0.5f * falloff));
        t[2] = 255;
        t[3] = std::uint8_t(255.0f * falloff);
      }
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kTextureSize, kTextureSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);

    std::uint32_t seed = 12345;
    for (int i = 0; i < kSprites; ++i) {
      Sprite s;
      s.x = next_random(seed) * 2.0f - 1.0f;
      s.y = next_random(seed) * 2.0f - 1.0f;
      s.vx = (next_random(seed) - 0.5f) * 0.02f;
      s.vy = (next_random(seed) - 0.5f) * 0.02f;
      s.r = 0.3f + 0.7f * next_random(seed);
      s.g = 0.3f + 0.7f * next_random(seed);
      s.b = 0.3f + 0.7f * next_random(seed);
      s.scale = 0.3f + 0.7f * next_random(seed);
      sprites_.push_back(s);
    }
    positions_.resize(kSprites * 6 * 2);
    corners_.resize(kSprites * 6 * 2);
    tints_.resize(kSprites * 6 * 4);
    static const float kCorners[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < kSprites; ++i)
      for (int v = 0; v < 6; ++v) {
        corners_[(i * 6 + v) * 2] = kCorners[v][0];
        corners_[(i * 6 + v) * 2 + 1] = kCorners[v][1];
        const Sprite& s = sprites_[i];
        float* tint = &tints_[(i * 6 + v) * 4];
        tint[0] = s.r, tint[1] = s.g, tint[2] = s.b, tint[3] = s.scale;
      }
    glClearColor(0.02f, 0.02f, 0.05f, 1.0f);
  }

  void draw(int frame) override {
    if (!program_) link();
    glClear(GL_COLOR_BUFFER_BIT);
    for (int i = 0; i < kSprites; ++i) {
      const Sprite& s = sprites_[i];
      // Positions wrap around the screen: [-1, 1) in both axes.
      const float x = std::fmod(s.x + s.vx * float(frame) + 3.0f, 2.0f) - 1.0f;
      const float y = std::fmod(s.y + s.vy * float(frame) + 3.0f, 2.0f) - 1.0f;
      for (int v = 0; v < 6; ++v) {
        positions_[(i * 6 + v) * 2] = x;
        positions_[(i * 6 + v) * 2 + 1] = y;
      }
    }
    glDrawArrays(GL_TRIANGLES, 0, kSprites * 6);
  }

  long trianglesPerFrame() const override { return 2L * kSprites; }

 private:
  struct Sprite {
    float x, y, vx, vy, r, g, b, scale;
  };

  void link() {
    program_ = demo::linkProgram("glsl_sprites", kVertex, kFragment, {"position", "corner", "tint"});
    glUseProgram(program_);
    glUniform1i(glGetUniformLocation(program_, "sprite_map"), 0);
    glUniform2f(glGetUniformLocation(program_, "pixel_size"), 2.0f / float(width_), 2.0f / float(height_));
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, positions_.data());
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 0, corners_.data());
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, 0, tints_.data());
    for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
  }

  int width_, height_;
  std::vector<Sprite> sprites_;
  std::vector<float> positions_, corners_, tints_;
  GLuint texture_ = 0, program_ = 0;
};

}  // namespace

std::unique_ptr<BenchScene> createGlslSprites(int width, int height) {
  return std::make_unique<GlslSprites>(width, height);
}

}  // namespace pineda::bench
