// A draw whose only change since the last is a uniform goes on with the last draw's record,
// with its own ShaderDraw (Scene::repeat_of_current_draw), and its geometry stage
// with it; a draw that changes a uniform and anything else (the program, blending, two-sided
// colours) gets a record of its own. Each cell of the surface is a quad of two triangles
// drawn after the uniform changes, and shows which record drew it.
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

constexpr int kCell = 16, kCells = 6;

const char* const kCellVertex =
    "attribute vec2 corner; uniform float cell; uniform vec4 front; uniform vec4 back;\n"
    "void main() {\n"
    "  gl_Position = vec4((cell + corner.x) * (2.0 / 6.0) - 1.0, corner.y * 2.0 - 1.0, 0.0, 1.0);\n"
    "  gl_FrontColor = front; gl_BackColor = back;\n"
    "}\n";

class UniformOnlyChangesTest : public ProgramTest {
 protected:
  SurfaceSpec spec() const override { return {kCell * kCells, kCell}; }

  GLuint program(const char* fragment, const char* vertex = kCellVertex) {
    const GLuint p = link_in_use(vertex, fragment, {{0, "corner"}});
    glEnableVertexAttribArray(0);
    return p;
  }
  // Cell `cell`'s quad, counter-clockwise (front-facing) or clockwise, with its colours set first.
  void quad(int cell, const Rgba& front, const Rgba& back = {0, 0, 0, 255}, bool clockwise = false) {
    GLint p = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &p);
    const GLuint program = GLuint(p);
    glUniform1f(glGetUniformLocation(program, "cell"), float(cell));
    glUniform4f(glGetUniformLocation(program, "front"), front[0] / 255.f, front[1] / 255.f, front[2] / 255.f, front[3] / 255.f);
    glUniform4f(glGetUniformLocation(program, "back"), back[0] / 255.f, back[1] / 255.f, back[2] / 255.f, back[3] / 255.f);
    static const GLfloat kCounterClockwise[] = {0, 0, 1, 0, 0, 1, 1, 1};
    static const GLfloat kClockwise[] = {0, 0, 0, 1, 1, 0, 1, 1};
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, clockwise ? kClockwise : kCounterClockwise);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
  }
  // The cell's pixels that are not `expected`.
  int wrong_in_cell(int cell, const Rgba& expected) {
    const std::vector<uint8_t> all = read_all();
    int wrong = 0;
    for (int y = 0; y < kCell; ++y)
      for (int x = cell * kCell; x < (cell + 1) * kCell; ++x) {
        const uint8_t* p = &all[(size_t(y) * width() + size_t(x)) * 4];
        wrong += p[0] != expected[0] || p[1] != expected[1] || p[2] != expected[2] || p[3] != expected[3];
      }
    return wrong;
  }
};

TEST_F(UniformOnlyChangesTest, EachDrawGetsItsOwnUniformsAndEverythingElseItChanged) {
  clear_to(0, 0, 0, 0);
  const GLuint plain = program("void main() { gl_FragColor = gl_Color; }\n");
  quad(0, {255, 0, 0, 255});
  quad(1, {0, 255, 0, 255});  // only uniforms changed: the record goes on, with these
  glEnable(GL_BLEND);  // and blending: a record of its own, which adds
  glBlendFunc(GL_ONE, GL_ONE);
  quad(1, {0, 0, 255, 255});
  glDisable(GL_BLEND);
  // Another program with the same uniforms and state, and a varying more: its own record and
  // geometry stage, not the last ones'.
  program("varying float scale; void main() { gl_FragColor = vec4(gl_Color.rgb * scale, 1.0); }\n",
          "attribute vec2 corner; uniform float cell; uniform vec4 front; uniform vec4 back; varying float scale;\n"
          "void main() {\n"
          "  gl_Position = vec4((cell + corner.x) * (2.0 / 6.0) - 1.0, corner.y * 2.0 - 1.0, 0.0, 1.0);\n"
          "  gl_FrontColor = front; gl_BackColor = back; scale = 0.5;\n"
          "}\n");
  quad(2, {0, 0, 254, 255});
  // Back-facing quads: the front colour until two-sided colours go on with the uniforms' change.
  glUseProgram(plain);
  quad(3, {255, 255, 0, 255}, {0, 255, 255, 255}, true);
  glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
  quad(4, {255, 255, 0, 255}, {255, 0, 255, 255}, true);
  quad(5, {255, 255, 0, 255}, {128, 128, 128, 255}, true);  // only uniforms changed again
  EXPECT_EQ(wrong_in_cell(0, {255, 0, 0, 255}), 0);
  EXPECT_EQ(wrong_in_cell(1, {0, 255, 255, 255}), 0);
  EXPECT_EQ(wrong_in_cell(2, {0, 0, 127, 255}), 0);
  EXPECT_EQ(wrong_in_cell(3, {255, 255, 0, 255}), 0);
  EXPECT_EQ(wrong_in_cell(4, {255, 0, 255, 255}), 0);
  EXPECT_EQ(wrong_in_cell(5, {128, 128, 128, 255}), 0);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Draws that each change a uniform, many more than a scene holds: scenes run and let their
// records go while the draws go on with the latest record and geometry stage; every cell shows
// its last draw's colour.
TEST_F(UniformOnlyChangesTest, ManyDrawsOfChangedUniformsOutliveTheirScenes) {
  clear_to(0, 0, 0, 0);
  program("void main() { gl_FragColor = gl_Color; }\n");
  for (int round = 0; round < 3000; ++round) quad(round % kCells, {uint8_t(round % 200), 10, 20, 255});
  for (int cell = 0; cell < kCells; ++cell) {
    const int last = 3000 - kCells + cell;  // the cell's last draw
    EXPECT_EQ(wrong_in_cell(cell, {uint8_t(last % 200), 10, 20, 255}), 0) << "cell " << cell;
  }
}

}  // namespace
}  // namespace pineda::test
