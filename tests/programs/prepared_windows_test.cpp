// A large programmable draw takes its vertices to the window ahead of assembly, on every
// thread (raster/geometry.h PreparedWindow); a small one as it goes. Both give the same
// pixels and depths: a jittered mesh with vertices outside the clip volume and behind the
// eye, front and back faces, culled and not, drawn at once and one triangle per draw.
#include <random>
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

class PreparedWindowsTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    link_in_use("attribute vec4 pos; attribute vec3 col; varying vec3 c;\n"
                "void main() { c = col; gl_Position = pos; }\n",
                "varying vec3 c; void main() { gl_FragColor = vec4(c, 1.0); }\n", {{0, "pos"}, {1, "col"}});
    glEnable(GL_DEPTH_TEST);
    // A grid of 50x40 cells (2091 vertices), jittered; some vertices beyond the guard band,
    // behind the eye (w < 0) or on the w = 0 plane; every third cell turned around.
    constexpr int kCols = 50, kRows = 40;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> jitter(-0.03f, 0.03f), unit(0.f, 1.f);
    for (int j = 0; j <= kRows; ++j)
      for (int i = 0; i <= kCols; ++i) {
        float x = -1.2f + 2.4f * i / kCols + jitter(rng), y = -1.1f + 2.2f * j / kRows + jitter(rng);
        float w = 1.f;
        if ((i * j) % 89 == 7) w = -0.5f;
        if ((i * j) % 97 == 11) w = 0.f;
        if ((i + 3 * j) % 113 == 0) x *= 4000.f;
        positions_.insert(positions_.end(), {x * w, y * w, unit(rng) * 1.6f - 0.8f, w});
        colours_.insert(colours_.end(), {unit(rng), unit(rng), unit(rng)});
      }
    const GLuint side = kCols + 1;
    for (GLuint j = 0; j < kRows; ++j)
      for (GLuint i = 0; i < kCols; ++i) {
        const GLuint v = j * side + i;
        if ((i + j) % 3 == 0) indices_.insert(indices_.end(), {v, v + side + 1, v + 1});
        else indices_.insert(indices_.end(), {v, v + 1, v + side + 1});
        indices_.insert(indices_.end(), {v, v + side + 1, v + side});
      }
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, positions_.data());
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, colours_.data());
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
  }

  using Image = ColourAndDepth;
  Image draw(bool at_once) {
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (at_once) {
      glDrawElements(GL_TRIANGLES, GLsizei(indices_.size()), GL_UNSIGNED_INT, indices_.data());
    } else {
      for (size_t t = 0; t < indices_.size(); t += 3) glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, &indices_[t]);
    }
    return read_colour_and_depth();
  }

  std::vector<GLfloat> positions_, colours_;
  std::vector<GLuint> indices_;
};

TEST_F(PreparedWindowsTest, ALargeDrawGivesThePixelsOfSmallOnes) {
  for (const bool cull : {false, true}) {
    if (cull) glEnable(GL_CULL_FACE);
    const Image at_once = draw(true), one_by_one = draw(false);
    EXPECT_EQ(at_once.colour, one_by_one.colour) << "cull " << cull;
    EXPECT_EQ(at_once.depth, one_by_one.depth) << "cull " << cull;
    int drawn = 0;
    for (size_t i = 0; i < at_once.colour.size(); i += 4) drawn += at_once.colour[i + 3] == 255;
    EXPECT_GT(drawn, width() * height() / 2) << "cull " << cull;
  }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// A small draw right after a large one of the same state (nothing read in between) takes its
// own vertices to the window, not the large draw's prepared ones.
TEST_F(PreparedWindowsTest, ASmallDrawAfterALargeOneOfTheSameStateDrawsItsOwnVertices) {
  glDisable(GL_DEPTH_TEST);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  // 400 red triangles over the left half, then one green triangle over the right half.
  std::vector<GLfloat> pos, col;
  for (int t = 0; t < 400; ++t) {
    pos.insert(pos.end(), {-1, -1, 0, 1, 0, -1, 0, 1, -1, 1, 0, 1});
    for (int v = 0; v < 3; ++v) col.insert(col.end(), {1, 0, 0});
  }
  pos.insert(pos.end(), {0, -1, 0, 1, 1, -1, 0, 1, 1, 1, 0, 1});
  for (int v = 0; v < 3; ++v) col.insert(col.end(), {0, 1, 0});
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, pos.data());
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, col.data());
  glDrawArrays(GL_TRIANGLES, 0, 1200);
  glDrawArrays(GL_TRIANGLES, 1200, 3);
  EXPECT_EQ(pixel(2, height() / 4), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(pixel(width() - 2, height() / 4), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
