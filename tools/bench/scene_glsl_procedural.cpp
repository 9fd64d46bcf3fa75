// GLSL 1.20, a long procedural fragment shader over the whole screen: two full-screen layers
// (the second blended over the first), each pixel running 6 octaves of value noise (a hash of
// fract and dot), then a colour ramp through mix/smoothstep and a few rings. No textures: all
// arithmetic, loops with constant bounds.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "bench_scene.h"
#include "demo/shader_program.h"

namespace pineda::bench {
namespace {

constexpr int kLayers = 2;

const char* const kVertex = R"(#version 120
attribute vec2 position;
varying vec2 v_uv;
void main() {
  v_uv = position * vec2(1.6, 1.2);
  gl_Position = vec4(position, 0.0, 1.0);
})";

const char* const kFragment = R"(#version 120
uniform float time;
uniform float layer;
varying vec2 v_uv;
// A hash without sin: sin of large arguments differs between implementations.
float hash(vec2 p) {
  vec3 q = fract(vec3(p.xyx) * 0.1031);
  q += dot(q, q.yzx + 33.33);
  return fract((q.x + q.y) * q.z);
}
float value_noise(vec2 p) {
  vec2 i = floor(p);
  vec2 f = fract(p);
  vec2 u = f * f * (3.0 - 2.0 * f);
  float a = hash(i), b = hash(i + vec2(1.0, 0.0));
  float c = hash(i + vec2(0.0, 1.0)), d = hash(i + vec2(1.0, 1.0));
  return mix(mix(a, b, u.x), mix(c, d, u.x), u.y);
}
void main() {
  vec2 p = v_uv * (3.0 + layer) + vec2(time * 0.1, layer * 7.0);
  float sum = 0.0, amplitude = 0.5;
  for (int octave = 0; octave < 6; ++octave) {
    sum += amplitude * value_noise(p);
    p = mat2(1.6, 1.2, -1.2, 1.6) * p;
    amplitude *= 0.5;
  }
  float rings = sin(length(v_uv) * 18.0 - time) * 0.5 + 0.5;
  vec3 low = vec3(0.05, 0.1, 0.3), high = vec3(0.95, 0.7, 0.3);
  vec3 color = mix(low, high, smoothstep(0.2, 0.8, sum));
  color += vec3(0.2, 0.1, 0.0) * rings * sum;
  gl_FragColor = vec4(clamp(color, 0.0, 1.0), 0.6);
})";

class GlslProcedural final : public BenchScene {
 public:
  GlslProcedural(int, int) { glClearColor(0.0f, 0.0f, 0.0f, 1.0f); }

  void draw(int frame) override {
    if (!program_) link();
    glClear(GL_COLOR_BUFFER_BIT);
    glUniform1f(time_, 0.25f * float(frame % 40));
    static const GLfloat positions[] = {-1, -1, 1, -1, 1, 1, -1, 1};
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, positions);
    for (int i = 0; i < kLayers; ++i) {
      if (i == 1) glEnable(GL_BLEND);
      glUniform1f(layer_, float(i));
      glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    }
    glDisable(GL_BLEND);
  }

  long trianglesPerFrame() const override { return 2L * kLayers; }

 private:
  void link() {
    program_ = demo::linkProgram("glsl_procedural", kVertex, kFragment, {"position"});
    glUseProgram(program_);
    time_ = glGetUniformLocation(program_, "time");
    layer_ = glGetUniformLocation(program_, "layer");
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnableVertexAttribArray(0);
  }

  GLuint program_ = 0;
  GLint time_ = -1, layer_ = -1;
};

}  // namespace

std::unique_ptr<BenchScene> createGlslProcedural(int width, int height) {
  return std::make_unique<GlslProcedural>(width, height);
}

}  // namespace pineda::bench
