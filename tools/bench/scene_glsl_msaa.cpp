// GLSL 1.20 into a 4x multisampled framebuffer object (a colour and a depth renderbuffer):
// two full-screen layers of a texture-heavy fragment shader (8 bilinear taps of a 256x256
// texture and some arithmetic per pixel, the second layer blended over the first, depth
// tested), and a fan of 64 thin triangles whose edges split many pixels' samples, then
// resolved into the window by glBlitFramebuffer. Measures the multisampled fragment path.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <vector>

#include "bench_scene.h"
#include "demo/multisample_target.h"
#include "demo/shader_program.h"

namespace pineda::bench {
namespace {

constexpr int kLayers = 2;
constexpr int kFanTriangles = 64;
constexpr int kTextureSize = 256;

const char* const kVertex = R"(#version 120
attribute vec3 position;
varying vec2 v_uv;
void main() {
  v_uv = position.xy * 0.5 + 0.5;
  gl_Position = vec4(position, 1.0);
})";

const char* const kFragment = R"(#version 120
uniform sampler2D image;
uniform float shift;
varying vec2 v_uv;
void main() {
  vec4 sum = vec4(0.0);
  for (int i = 0; i < 8; ++i) {
    float a = float(i) * 0.785398 + shift;
    sum += texture2D(image, v_uv * 1.5 + vec2(cos(a), sin(a)) * 0.01);
  }
  vec3 color = sum.rgb / 8.0;
  color = color * color * (3.0 - 2.0 * color);
  gl_FragColor = vec4(color, 0.7);
})";

class GlslMsaa final : public BenchScene {
 public:
  GlslMsaa(int width, int height) : width_(width), height_(height) { glClearColor(0.f, 0.f, 0.f, 1.f); }

  void draw(int frame) override {
    if (!program_) setUp();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    static const GLfloat quad[] = {-1, -1, 0.5f, 1, -1, 0.5f, 1, 1, 0.5f, -1, 1, 0.5f};
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, quad);
    for (int i = 0; i < kLayers; ++i) {
      if (i == 1) glEnable(GL_BLEND);
      glUniform1f(shift_, 0.1f * float(frame % 30) + float(i));
      glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    }
    glDisable(GL_BLEND);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, fan_.data());
    glDrawArrays(GL_TRIANGLES, 0, 3 * kFanTriangles);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  long trianglesPerFrame() const override { return 2L * kLayers + kFanTriangles; }

 private:
  void setUp() {
    program_ = demo::linkProgram("glsl_msaa", kVertex, kFragment, {"position"});
    glUseProgram(program_);
    shift_ = glGetUniformLocation(program_, "shift");
    glUniform1i(glGetUniformLocation(program_, "image"), 0);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnableVertexAttribArray(0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);

    std::vector<unsigned char> texels(kTextureSize * kTextureSize * 4);
    for (int y = 0; y < kTextureSize; ++y)
      for (int x = 0; x < kTextureSize; ++x) {
        unsigned char* t = &texels[size_t(y * kTextureSize + x) * 4];
        t[0] = static_cast<unsigned char>((x * 7) ^ (y * 3));
        t[1] = static_cast<unsigned char>(((x / 16 + y / 16) & 1) ? 220 : 40);
        t[2] = static_cast<unsigned char>(x + y);
        t[3] = 255;
      }
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kTextureSize, kTextureSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());

    // Thin triangles from the centre, nearer than the layers.
    for (int i = 0; i < kFanTriangles; ++i) {
      const float a0 = 6.2831853f * float(i) / kFanTriangles, a1 = a0 + 0.03f;
      const GLfloat tri[9] = {0.f, 0.f, 0.2f, 1.4f * std::cos(a0), 1.4f * std::sin(a0), 0.2f,
                              1.4f * std::cos(a1), 1.4f * std::sin(a1), 0.2f};
      fan_.insert(fan_.end(), tri, tri + 9);
    }

    framebuffer_ = demo::makeMultisampleTarget("glsl_msaa", width_, height_, 4).framebuffer;
  }

  int width_, height_;
  GLuint program_ = 0, texture_ = 0, framebuffer_ = 0;
  GLint shift_ = -1;
  std::vector<GLfloat> fan_;
};

}  // namespace

std::unique_ptr<BenchScene> createGlslMsaa(int width, int height) { return std::make_unique<GlslMsaa>(width, height); }

}  // namespace pineda::bench
