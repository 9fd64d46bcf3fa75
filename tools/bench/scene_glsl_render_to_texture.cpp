// GLSL 1.20, render to texture: each frame draws 16 depth-tested, per-vertex lit rotating
// quads (each about a sixth of the target wide) into a 512x512 RGBA8 texture of a framebuffer object (with a 24-bit depth
// renderbuffer), then composites that texture over the whole window twice with a 5-tap blur
// and vignette fragment shader (the second pass blended and shifted).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>

#include "bench_scene.h"
#include "demo/shader_program.h"
#include "demo/texture_target.h"

namespace pineda::bench {
namespace {

constexpr int kTargetSize = 512;
constexpr int kQuads = 16;

const char* const kSceneVertex = R"(#version 120
attribute vec2 position;
uniform vec4 placement;  // xy: centre, z: angle, w: depth
uniform vec3 tint;
varying vec3 v_color;
void main() {
  float c = cos(placement.z), s = sin(placement.z);
  vec2 p = mat2(c, s, -s, c) * position * 0.35;
  vec3 normal = normalize(vec3(position * 0.8, 1.0));
  float light = max(dot(normal, normalize(vec3(0.4, 0.6, 1.0))), 0.0);
  v_color = tint * (0.2 + 0.8 * light);
  gl_Position = vec4(p + placement.xy, placement.w, 1.0);
})";

const char* const kSceneFragment = R"(#version 120
varying vec3 v_color;
void main() { gl_FragColor = vec4(v_color, 1.0); }
)";

const char* const kCompositeVertex = R"(#version 120
attribute vec2 position;
uniform vec2 shift;
varying vec2 v_texcoord;
void main() {
  v_texcoord = position * 0.5 + 0.5 + shift;
  gl_Position = vec4(position, 0.0, 1.0);
})";

const char* const kCompositeFragment = R"(#version 120
uniform sampler2D frame_map;
uniform float texel;
varying vec2 v_texcoord;
void main() {
  vec4 sum = texture2D(frame_map, v_texcoord) * 0.4;
  sum += texture2D(frame_map, v_texcoord + vec2(texel, 0.0)) * 0.15;
  sum += texture2D(frame_map, v_texcoord - vec2(texel, 0.0)) * 0.15;
  sum += texture2D(frame_map, v_texcoord + vec2(0.0, texel)) * 0.15;
  sum += texture2D(frame_map, v_texcoord - vec2(0.0, texel)) * 0.15;
  vec2 centred = v_texcoord - 0.5;
  float vignette = 1.0 - dot(centred, centred) * 1.2;
  gl_FragColor = vec4(sum.rgb * vignette, 0.5);
})";

class GlslRenderToTexture final : public BenchScene {
 public:
  GlslRenderToTexture(int width, int height) : width_(width), height_(height) {
    // Bound to unit 0 from here on: the composite passes sample it.
    target_ = demo::makeTextureTarget("glsl_rtt", kTargetSize, GL_DEPTH_COMPONENT24);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  }

  void draw(int frame) override {
    if (!scene_program_) link();
    static const GLfloat quad[] = {-1, -1, 1, -1, 1, 1, -1, 1};
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, quad);

    glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer);
    glViewport(0, 0, kTargetSize, kTargetSize);
    glClearColor(0.1f, 0.15f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glUseProgram(scene_program_);
    for (int i = 0; i < kQuads; ++i) {
      const float angle = 0.05f * float(frame) + 0.7f * float(i);
      glUniform4f(placement_, 0.6f * std::cos(0.4f * float(i)), 0.6f * std::sin(0.9f * float(i)), angle,
                  float(i) / kQuads * 1.6f - 0.8f);
      glUniform3f(tint_, 0.4f + 0.6f * float(i % 3) / 2.0f, 0.4f + 0.6f * float(i % 5) / 4.0f,
                  0.4f + 0.6f * float(i % 7) / 6.0f);
      glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    }
    glDisable(GL_DEPTH_TEST);

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width_, height_);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glUseProgram(composite_program_);
    glUniform2f(shift_, 0.0f, 0.0f);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    glEnable(GL_BLEND);
    glUniform2f(shift_, 0.01f, 0.005f);
    glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    glDisable(GL_BLEND);
  }

  long trianglesPerFrame() const override { return 2L * kQuads + 4; }

 private:
  void link() {
    scene_program_ = demo::linkProgram("glsl_render_to_texture", kSceneVertex, kSceneFragment, {"position"});
    placement_ = glGetUniformLocation(scene_program_, "placement");
    tint_ = glGetUniformLocation(scene_program_, "tint");
    composite_program_ = demo::linkProgram("glsl_render_to_texture", kCompositeVertex, kCompositeFragment, {"position"});
    glUseProgram(composite_program_);
    glUniform1i(glGetUniformLocation(composite_program_, "frame_map"), 0);
    glUniform1f(glGetUniformLocation(composite_program_, "texel"), 1.5f / kTargetSize);
    shift_ = glGetUniformLocation(composite_program_, "shift");
    glEnableVertexAttribArray(0);
  }

  int width_, height_;
  demo::TextureTarget target_;
  GLuint scene_program_ = 0, composite_program_ = 0;
  GLint placement_ = -1, tint_ = -1, shift_ = -1;
};

}  // namespace

std::unique_ptr<BenchScene> createGlslRenderToTexture(int width, int height) {
  return std::make_unique<GlslRenderToTexture>(width, height);
}

}  // namespace pineda::bench
