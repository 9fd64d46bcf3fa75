// GLSL 1.20, vertex-shader heavy: a 320x320 grid (204800 triangles, 103041 vertices in buffer
// objects) bent by 8 animated bones, each vertex blending four bone matrices picked by
// attribute indices (dynamically indexed uniform array), its normal lit in the vertex shader;
// the fragment shader only writes the colour. The program is compiled and linked in frame 0,
// so the "first ms" column is compile + link + first frame.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "bench_scene.h"
#include "demo/shader_program.h"

namespace pineda::bench {
namespace {

constexpr int kGrid = 320;
constexpr int kBones = 8;

const char* const kVertex = R"(#version 120
attribute vec3 position;
attribute vec3 normal;
attribute vec4 weights;
attribute vec4 bone_index;
uniform mat4 bones[8];
uniform mat4 view_projection;
uniform vec3 light_direction;
uniform vec3 base_color;
varying vec3 v_color;
void main() {
  mat4 skin = bones[int(bone_index.x)] * weights.x + bones[int(bone_index.y)] * weights.y +
              bones[int(bone_index.z)] * weights.z + bones[int(bone_index.w)] * weights.w;
  vec4 p = skin * vec4(position, 1.0);
  vec3 n = normalize(mat3(skin) * normal);
  float diffuse = max(dot(n, light_direction), 0.0);
  v_color = base_color * (0.25 + 0.75 * diffuse);
  gl_Position = view_projection * p;
})";

const char* const kFragment = R"(#version 120
varying vec3 v_color;
void main() {
  gl_FragColor = vec4(v_color, 1.0);
})";

struct SkinVertex {
  float position[3], normal[3], weights[4], bones[4];
};

class GlslSkinned final : public BenchScene {
 public:
  GlslSkinned(int width, int height) {
    std::vector<SkinVertex> vertices;
    for (int j = 0; j <= kGrid; ++j)
      for (int i = 0; i <= kGrid; ++i) {
        const float x = -1.0f + 2.0f * float(i) / kGrid, y = -1.0f + 2.0f * float(j) / kGrid;
        // Bones along x; each vertex between bone b and b+1, a little of b-1 and b+2.
        const float along = (x + 1.0f) * 0.5f * float(kBones - 1);
        const int b = std::min(int(along), kBones - 2);
        const float f = along - float(b);
        SkinVertex v{{x, y, 0.0f}, {0.0f, 0.0f, 1.0f},
                     {0.9f * (1.0f - f), 0.9f * f, 0.05f, 0.05f},
                     {float(b), float(b + 1), float(std::max(b - 1, 0)), float(std::min(b + 2, kBones - 1))}};
        vertices.push_back(v);
      }
    std::vector<GLuint> indices;
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) {
        const GLuint a = GLuint(j * (kGrid + 1) + i), c = a + kGrid + 1;
        for (GLuint k : {a, a + 1, c, c, a + 1, c + 1}) indices.push_back(k);
      }
    indexCount_ = GLsizei(indices.size());
    glGenBuffers(2, buffers_);
    glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(SkinVertex)), vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(GLuint)), indices.data(),
                 GL_STATIC_DRAW);
    glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    setCamera(float(width) / float(height));
  }

  void draw(int frame) override {
    if (!program_) link();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    // Bone k turns about the y axis by an angle growing along the chain, around its own x.
    GLfloat bones[kBones][16];
    for (int k = 0; k < kBones; ++k) {
      const float angle = 0.25f * float(k) * std::sin(0.2f * float(frame) + 0.5f * float(k));
      const float c = std::cos(angle), s = std::sin(angle);
      const float pivot = -1.0f + 2.0f * float(k) / float(kBones - 1);
      const GLfloat m[16] = {c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, pivot - c * pivot, 0, s * pivot, 1};
      std::copy(m, m + 16, bones[k]);
    }
    glUniformMatrix4fv(bonesLocation_, kBones, GL_FALSE, &bones[0][0]);
    glUniformMatrix4fv(viewProjectionLocation_, 1, GL_FALSE, viewProjection_);
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  }

  long trianglesPerFrame() const override { return 2L * kGrid * kGrid; }

 private:
  // Perspective (vertical field of view 0.9 rad) times a camera 3 units back, tilted by 0.5 rad
  // about x; column-major.
  void setCamera(float aspect) {
    const float f = 1.0f / std::tan(0.45f), near = 0.5f, far = 10.0f;
    const float projection[16] = {f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) / (near - far), -1,
                                  0, 0, 2 * far * near / (near - far), 0};
    const float c = std::cos(-0.5f), s = std::sin(-0.5f);
    const float view[16] = {1, 0, 0, 0, 0, c, s, 0, 0, -s, c, 0, 0, 0, -3, 1};
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 4; ++row) {
        float sum = 0;
        for (int k = 0; k < 4; ++k) sum += projection[k * 4 + row] * view[col * 4 + k];
        viewProjection_[col * 4 + row] = sum;
      }
  }

  void link() {
    program_ = demo::linkProgram("glsl_skinned", kVertex, kFragment, {"position", "normal", "weights", "bone_index"});
    glUseProgram(program_);
    bonesLocation_ = glGetUniformLocation(program_, "bones");
    viewProjectionLocation_ = glGetUniformLocation(program_, "view_projection");
    glUniform3f(glGetUniformLocation(program_, "light_direction"), 0.3f, 0.4f, 0.866f);
    glUniform3f(glGetUniformLocation(program_, "base_color"), 0.9f, 0.7f, 0.4f);
    const GLsizei stride = sizeof(SkinVertex);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(SkinVertex, position)));
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(SkinVertex, normal)));
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(SkinVertex, weights)));
    glVertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(SkinVertex, bones)));
    for (GLuint i = 0; i < 4; ++i) glEnableVertexAttribArray(i);
  }

  GLfloat viewProjection_[16] = {};
  GLuint buffers_[2] = {}, program_ = 0;
  GLint bonesLocation_ = -1, viewProjectionLocation_ = -1;
  GLsizei indexCount_ = 0;
};

}  // namespace

std::unique_ptr<BenchScene> createGlslSkinned(int width, int height) {
  return std::make_unique<GlslSkinned>(width, height);
}

}  // namespace pineda::bench
