// Draw-call overhead with nothing changing between the calls: 20000 one-triangle glDrawArrays
// (a 160x125 grid of small smooth-shaded triangles, about 18 pixels each at 1024x768) from one
// vertex buffer object, each call drawing its own three vertices; fixed function (small_draws)
// or through a GLSL 1.20 program whose uniforms stay as they are (glsl_small_draws). The bench
// reports the calling thread's time per draw and the frame's.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdint>
#include <vector>

#include "bench_scene.h"
#include "demo/shader_program.h"

namespace pineda::bench {
namespace {

constexpr int kColumns = 160, kRows = 125;

struct Vertex {
  float x, y;
  std::uint8_t rgba[4];
};

const char* const kVertex = R"(#version 120
attribute vec2 position;
attribute vec4 color;
uniform vec2 scale;
varying vec4 v_color;
void main() {
  v_color = color;
  gl_Position = vec4(position * scale, 0.0, 1.0);
})";

const char* const kFragment = R"(#version 120
varying vec4 v_color;
void main() { gl_FragColor = v_color; }
)";

// The grid in a buffer object, drawn one triangle per call.
class SmallDraws : public BenchScene {
 public:
  SmallDraws(int, int) {
    std::vector<Vertex> vertices;
    vertices.reserve(std::size_t(3) * kColumns * kRows);
    const float w = 2.0f / kColumns, h = 2.0f / kRows;
    for (int row = 0; row < kRows; ++row)
      for (int column = 0; column < kColumns; ++column) {
        const float x = -1.0f + w * float(column), y = -1.0f + h * float(row);
        const auto shade = [](int v, int n) { return std::uint8_t(64 + 191 * v / (n - 1)); };
        vertices.push_back({x, y, {shade(column, kColumns), 40, shade(row, kRows), 255}});
        vertices.push_back({x + w * 0.8f, y, {255, shade(row, kRows), 40, 255}});
        vertices.push_back({x, y + h * 0.8f, {40, 255, shade(column, kColumns), 255}});
      }
    glGenBuffers(1, &buffer_);
    glBindBuffer(GL_ARRAY_BUFFER, buffer_);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(Vertex)), vertices.data(), GL_STATIC_DRAW);
    glVertexPointer(2, GL_FLOAT, sizeof(Vertex), nullptr);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), colorOffset());
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glShadeModel(GL_SMOOTH);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  }

  void draw(int frame) override {
    glClear(GL_COLOR_BUFFER_BIT);
    // The grid drawn from a different first cell each frame: the same calls, in another order.
    const int cells = kColumns * kRows, start = (frame * 997) % cells;
    for (int i = 0; i < cells; ++i) glDrawArrays(GL_TRIANGLES, 3 * ((start + i) % cells), 3);
  }

  long trianglesPerFrame() const override { return long{kColumns} * kRows; }
  long drawCallsPerFrame() const override { return long{kColumns} * kRows; }

 protected:
  static const void* colorOffset() { return reinterpret_cast<const void*>(offsetof(Vertex, rgba)); }

 private:
  GLuint buffer_ = 0;
};

// The same draws through a program: generic attributes from the same buffer, one uniform set once.
class GlslSmallDraws final : public SmallDraws {
 public:
  GlslSmallDraws(int width, int height) : SmallDraws(width, height) {
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    program_ = demo::linkProgram("glsl_small_draws", kVertex, kFragment, {"position", "color"});
    glUseProgram(program_);
    glUniform2f(glGetUniformLocation(program_, "scale"), 1.0f, 1.0f);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
    glVertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex), colorOffset());
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
  }

 private:
  GLuint program_ = 0;
};

}  // namespace

std::unique_ptr<BenchScene> createSmallDraws(int width, int height) {
  return std::make_unique<SmallDraws>(width, height);
}

std::unique_ptr<BenchScene> createGlslSmallDraws(int width, int height) {
  return std::make_unique<GlslSmallDraws>(width, height);
}

}  // namespace pineda::bench
