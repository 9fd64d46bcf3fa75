// GLSL 1.20, per-pixel lighting over overdraw: 6 full-screen layers (no depth test, so every
// layer shades every pixel), each with its own corner normals, shaded by a Blinn-Phong fragment
// shader (normalize, dot, pow) that modulates a bilinear-filtered RGBA8 texture. The program is
// compiled and linked in frame 0, so the "first ms" column is compile + link + first frame.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

#include "bench_scene.h"
#include "demo/shader_program.h"

namespace pineda::bench {
namespace {

constexpr int kLayers = 6;
constexpr int kTextureSize = 256;

const char* const kVertex = R"(#version 120
attribute vec2 position;
attribute vec3 normal;
uniform float layer;
varying vec3 v_normal;
varying vec3 v_eye;
varying vec2 v_texcoord;
void main() {
  v_normal = normal;
  v_eye = vec3(position * 2.0, -3.0 - layer);
  v_texcoord = position * (1.5 + 0.25 * layer) + vec2(0.1 * layer, 0.0);
  gl_Position = vec4(position, 0.0, 1.0);
})";

const char* const kFragment = R"(#version 120
uniform sampler2D base_map;
uniform vec3 light_direction;
uniform vec3 light_color;
uniform float shininess;
varying vec3 v_normal;
varying vec3 v_eye;
varying vec2 v_texcoord;
void main() {
  vec3 n = normalize(v_normal);
  vec3 l = normalize(light_direction);
  vec3 h = normalize(l + normalize(-v_eye));
  float diffuse = max(dot(n, l), 0.0);
  float specular = pow(max(dot(n, h), 0.0), shininess);
  vec4 base = texture2D(base_map, v_texcoord);
  vec3 color = base.rgb * (vec3(0.15) + light_color * diffuse) + vec3(0.5) * specular;
  gl_FragColor = vec4(color, base.a);
})";

class GlslLit final : public BenchScene {
 public:
  GlslLit(int, int) {
    std::vector<std::uint8_t> texels(kTextureSize * kTextureSize * 4);
    for (int y = 0; y < kTextureSize; ++y)
      for (int x = 0; x < kTextureSize; ++x) {
        std::uint8_t* t = &texels[(y * kTextureSize + x) * 4];
        const bool odd = ((x / 16) ^ (y / 16)) & 1;
        t[0] = std::uint8_t(odd ? 220 : 40 + x / 2);
        t[1] = std::uint8_t(odd ? 180 : 60 + y / 2);
        t[2] = std::uint8_t(odd ? 90 : 200);
        t[3] = 255;
      }
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kTextureSize, kTextureSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
  }

  void draw(int frame) override {
    if (!program_) link();
    glClear(GL_COLOR_BUFFER_BIT);
    const float swing = 0.05f * float(frame % 20);
    glUniform3f(glGetUniformLocation(program_, "light_direction"), 0.3f + swing, 0.5f, 1.0f);
    for (int i = 0; i < kLayers; ++i) {
      glUniform1f(layer_, float(i));
      const float tilt = 0.6f * float(i % 3 - 1), lean = 0.4f * float(i % 2 ? 1 : -1);
      const GLfloat positions[] = {-1, -1, 1, -1, 1, 1, -1, 1};
      const GLfloat normals[] = {-0.5f + tilt, -0.5f, 1,   0.5f + tilt, -0.5f + lean, 1,
                                 0.5f + tilt, 0.5f, 1,     -0.5f + tilt, 0.5f - lean, 1};
      glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, positions);
      glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, normals);
      glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
    }
  }

  long trianglesPerFrame() const override { return 2L * kLayers; }

 private:
  void link() {
    program_ = demo::linkProgram("glsl_lit", kVertex, kFragment, {"position", "normal"});
    glUseProgram(program_);
    glUniform1i(glGetUniformLocation(program_, "base_map"), 0);
    glUniform3f(glGetUniformLocation(program_, "light_color"), 0.9f, 0.85f, 0.8f);
    glUniform1f(glGetUniformLocation(program_, "shininess"), 32.0f);
    layer_ = glGetUniformLocation(program_, "layer");
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
  }

  GLuint texture_ = 0, program_ = 0;
  GLint layer_ = -1;
};

}  // namespace

std::unique_ptr<BenchScene> createGlslLit(int width, int height) { return std::make_unique<GlslLit>(width, height); }

}  // namespace pineda::bench
