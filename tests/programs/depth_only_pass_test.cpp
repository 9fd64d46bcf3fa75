// A program's draw that writes no colour (colour mask off) after early depth tests: Pineda runs
// no shader for it (raster/shader_quads.cpp, runs_shader), and the depth buffer and the
// occlusion query's count must be those of the same draw with colour writes on, the colour
// buffer untouched. Triangles from a few pixels (blocks of several triangles) to tens of pixels
// across (whole blocks), over one another.
#include <random>
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

const char* const kDepthOnlyVertex = R"(#version 120
attribute vec4 position;
varying vec4 v_position;
void main() {
  v_position = position;
  gl_Position = position;
})";

const char* const kDepthOnlyFragment = R"(#version 120
varying vec4 v_position;
void main() { gl_FragColor = vec4(fract(v_position.xyz * 7.0), 1.0); })";

class DepthOnlyPassTest : public ProgramTest {
 protected:
  SurfaceSpec spec() const override { return {64, 64, 24, 8}; }

  struct Result {
    std::vector<uint32_t> depth;
    std::vector<uint8_t> color;
    GLuint samples = 0;
  };

  Result render(const std::vector<float>& positions, bool color_writes) {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const GLboolean write = color_writes ? GL_TRUE : GL_FALSE;
    glColorMask(write, write, write, write);
    GLuint query = 0;
    glGenQueries(1, &query);
    glBeginQuery(GL_SAMPLES_PASSED, query);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, positions.data());
    glEnableVertexAttribArray(0);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(positions.size() / 4));
    glEndQuery(GL_SAMPLES_PASSED);
    Result r;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &r.samples);
    glDeleteQueries(1, &query);
    r.depth.resize(64 * 64);
    glReadPixels(0, 0, 64, 64, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, r.depth.data());
    r.color = read_all();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return r;
  }
};

TEST_F(DepthOnlyPassTest, DepthAndSamplesAsWithColourWrites) {
  link_in_use(kDepthOnlyVertex, kDepthOnlyFragment, {{0, "position"}});
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  std::vector<float> positions;
  for (int t = 0; t < 600; ++t) {
    const float size = t % 3 == 0 ? 0.6f : 0.1f;  // about 19 or 3 pixels across
    const float cx = unit(random) * 1.8f - 0.9f, cy = unit(random) * 1.8f - 0.9f;
    for (int v = 0; v < 3; ++v) {
      positions.insert(positions.end(), {cx + (unit(random) - 0.5f) * size, cy + (unit(random) - 0.5f) * size,
                                         unit(random) * 1.8f - 0.9f, 1.f});
    }
  }
  const Result with_color = render(positions, true);
  const Result depth_only = render(positions, false);
  EXPECT_EQ(depth_only.samples, with_color.samples);
  EXPECT_GT(with_color.samples, 3000u);
  int differing = 0, written = 0;
  for (size_t i = 0; i < with_color.depth.size(); ++i) {
    differing += depth_only.depth[i] != with_color.depth[i];
    written += with_color.depth[i] != 0xFFFFFFFFu;
  }
  EXPECT_EQ(differing, 0);
  EXPECT_GT(written, 2000);  // most of the 4096 pixels
  // The colour buffer keeps the clear colour where the colour mask is off.
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClear(GL_COLOR_BUFFER_BIT);
  EXPECT_EQ(depth_only.color, read_all());
  EXPECT_NE(with_color.color, depth_only.color);
}

}  // namespace
}  // namespace pineda::test
