// Small triangles of one draw share shader blocks (raster/shader_quads.h, ShaderQuadBatch):
// quads of several triangles and rows in one block. The image must be the one each triangle
// gives drawn by itself (one draw each: nothing packed across draws), where order matters
// (blending, depth, triangles over one another) and where quads of different triangles meet in
// a block (facing, gl_FragCoord, varyings, discard).
#include <random>
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

const char* const kVertex = R"(#version 120
attribute vec4 position;
attribute vec4 color;
varying vec4 v_color;
void main() {
  v_color = color;
  gl_Position = position;
})";

// Facing, the window position and a discard make the neighbours in a block tell apart.
const char* const kFragment = R"(#version 120
varying vec4 v_color;
void main() {
  if (v_color.b > 0.9) discard;
  vec3 facing = gl_FrontFacing ? v_color.rgb : v_color.gbr;
  gl_FragColor = vec4(facing * fract(gl_FragCoord.x * 0.13 + gl_FragCoord.y * 0.07 + 0.3), v_color.a);
})";

class PackedSmallTrianglesTest : public ProgramTest {
 protected:
  SurfaceSpec spec() const override { return {64, 64}; }

  struct Vertex {
    float position[4];
    float color[4];
  };

  // `count` triangles at most 7 pixels across (both windings), many over one another, at three
  // depths.
  std::vector<Vertex> triangles(unsigned seed, int count) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<float> centre(-0.9f, 0.9f), offset(-3.5f / 32.f, 3.5f / 32.f), unit(0.f, 1.f);
    std::uniform_int_distribution<int> level(-1, 1);
    std::vector<Vertex> out;
    for (int t = 0; t < count; ++t) {
      const float cx = centre(random) * 0.5f, cy = centre(random) * 0.5f;  // the middle of the buffer
      const float color[4] = {unit(random), unit(random), unit(random), 0.2f + 0.7f * unit(random)};
      const float z = 0.5f * static_cast<float>(level(random));  // equal depths: LEQUAL lets the later win
      for (int v = 0; v < 3; ++v)
        out.push_back({{cx + offset(random), cy + offset(random), z, 1.f}, {color[0], color[1], color[2], color[3]}});
    }
    return out;
  }

  std::vector<uint8_t> render(const std::vector<Vertex>& vertices, bool one_draw) {
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), vertices[0].position);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(Vertex), vertices[0].color);
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    const auto count = static_cast<GLsizei>(vertices.size());
    if (one_draw) {
      glDrawArrays(GL_TRIANGLES, 0, count);
    } else {
      for (GLsizei first = 0; first < count; first += 3) glDrawArrays(GL_TRIANGLES, first, 3);
    }
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return read_all();
  }

  // One draw and one draw per triangle give the same image, and it depends on the order.
  void expect_packed_as_alone(unsigned seed) {
    link_in_use(kVertex, kFragment, {{0, "position"}, {1, "color"}});
    std::vector<Vertex> vertices = triangles(seed, 3000);
    const std::vector<uint8_t> alone = render(vertices, false), packed = render(vertices, true);
    ASSERT_EQ(packed.size(), alone.size());
    int differing = 0;
    for (size_t i = 0; i < packed.size(); ++i) differing += packed[i] != alone[i];
    EXPECT_EQ(differing, 0);
    // The same triangles the other way round draw another image: the comparison sees order.
    std::vector<Vertex> reversed(vertices.rbegin(), vertices.rend());
    EXPECT_NE(render(reversed, true), packed);
  }
};

TEST_F(PackedSmallTrianglesTest, BlendedOverOneAnotherInOrder) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  expect_packed_as_alone(1);
}

TEST_F(PackedSmallTrianglesTest, DepthTestedInOrder) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  expect_packed_as_alone(2);
}

TEST_F(PackedSmallTrianglesTest, DepthTestedAndBlendedInOrder) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  expect_packed_as_alone(3);
}

TEST_F(PackedSmallTrianglesTest, StencilCountsEveryFragmentInOrder) {
  glEnable(GL_STENCIL_TEST);
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glStencilFunc(GL_EQUAL, 0, 0xff);  // a pixel's first fragment alone passes
  glStencilOp(GL_INCR, GL_INCR, GL_INCR);
  link_in_use(kVertex, kFragment, {{0, "position"}, {1, "color"}});
  const std::vector<Vertex> vertices = triangles(4, 3000);
  const std::vector<uint8_t> alone = render(vertices, false);
  glClear(GL_STENCIL_BUFFER_BIT);
  EXPECT_EQ(render(vertices, true), alone);
}

TEST_F(PackedSmallTrianglesTest, OcclusionQueriesCountTheSamePixels) {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  link_in_use(kVertex, kFragment, {{0, "position"}, {1, "color"}});
  const std::vector<Vertex> vertices = triangles(5, 3000);
  GLuint query = 0;
  glGenQueries(1, &query);
  auto samples_passed = [&](bool one_draw) {
    glBeginQuery(GL_SAMPLES_PASSED, query);
    render(vertices, one_draw);
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint passed = 0;
    glGetQueryObjectuiv(query, GL_QUERY_RESULT, &passed);
    return passed;
  };
  const GLuint alone = samples_passed(false);
  EXPECT_GT(alone, 500u);  // (each pixel at most three times: three depths, LESS)
  EXPECT_EQ(samples_passed(true), alone);
  glDeleteQueries(1, &query);
}

}  // namespace
}  // namespace pineda::test
