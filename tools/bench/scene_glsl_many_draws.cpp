// GLSL 1.20, draw-call overhead: 12288 one-quad draws (a 128x96 grid of 6x6-pixel quads at
// 1024x768), each after two glUniform calls (its offset and colour), through one program.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include "bench_scene.h"
#include "demo/shader_program.h"

namespace pineda::bench {
namespace {

constexpr int kColumns = 128;
constexpr int kRows = 96;

const char* const kVertex = R"(#version 120
attribute vec2 position;
uniform vec2 offset;
uniform vec2 cell;
void main() { gl_Position = vec4(offset + position * cell * 0.75, 0.0, 1.0); }
)";

const char* const kFragment = R"(#version 120
uniform vec4 color;
void main() { gl_FragColor = color; }
)";

class GlslManyDraws final : public BenchScene {
 public:
  GlslManyDraws(int, int) { glClearColor(0.0f, 0.0f, 0.0f, 1.0f); }

  void draw(int frame) override {
    if (!program_) link();
    glClear(GL_COLOR_BUFFER_BIT);
    const float cellWidth = 2.0f / kColumns, cellHeight = 2.0f / kRows;
    for (int row = 0; row < kRows; ++row)
      for (int column = 0; column < kColumns; ++column) {
        glUniform2f(offset_, -1.0f + cellWidth * (float(column) + 0.5f), -1.0f + cellHeight * (float(row) + 0.5f));
        const int hue = (row * 7 + column * 3 + frame) % 64;
        glUniform4f(color_, float(hue) / 63.0f, float(row) / (kRows - 1), float(column) / (kColumns - 1), 1.0f);
        glDrawArrays(GL_TRIANGLE_FAN, 0, 4);
      }
  }

  long trianglesPerFrame() const override { return 2L * kColumns * kRows; }
  long drawCallsPerFrame() const override { return long{kColumns} * kRows; }

 private:
  void link() {
    program_ = demo::linkProgram("glsl_many_draws", kVertex, kFragment, {"position"});
    glUseProgram(program_);
    offset_ = glGetUniformLocation(program_, "offset");
    color_ = glGetUniformLocation(program_, "color");
    glUniform2f(glGetUniformLocation(program_, "cell"), 1.0f / kColumns, 1.0f / kRows);
    static const GLfloat quad[] = {-1, -1, 1, -1, 1, 1, -1, 1};
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, quad);
    glEnableVertexAttribArray(0);
  }

  GLuint program_ = 0;
  GLint offset_ = -1, color_ = -1;
};

}  // namespace

std::unique_ptr<BenchScene> createGlslManyDraws(int width, int height) {
  return std::make_unique<GlslManyDraws>(width, height);
}

}  // namespace pineda::bench
