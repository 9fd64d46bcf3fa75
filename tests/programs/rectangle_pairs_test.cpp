// Sprites drawn as two triangles each are rasterized as rectangles (raster/rectangle_pair.h):
// a draw of many (its windows prepared ahead), a draw per sprite and a draw per triangle (which
// pairs nothing) give the same pixels and depths.
#include <random>
#include <vector>

#include "tests/programs/program_test.h"

namespace pineda::test {
namespace {

class RectanglePairsTest : public ProgramTest {
 protected:
  void SetUp() override {
    ProgramTest::SetUp();
    link_in_use("attribute vec4 pos; attribute vec2 corner; attribute vec3 tint; varying vec2 uv; varying vec3 t;\n"
                "void main() { uv = corner * 0.5 + 0.5; t = tint; gl_Position = pos; }\n",
                "varying vec2 uv; varying vec3 t; void main() { gl_FragColor = vec4(uv * t.xy, t.z, 1.0); }\n",
                {{0, "pos"}, {1, "corner"}, {2, "tint"}});
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    std::mt19937 rng(53);
    std::uniform_real_distribution<float> unit(0.f, 1.f);
    static const float kCorners[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < kSprites; ++i) {
      const float x = unit(rng) * 2.2f - 1.1f, y = unit(rng) * 2.2f - 1.1f, z = unit(rng) * 1.8f - 0.9f;
      const float half_w = 0.01f + 0.2f * unit(rng), half_h = 0.01f + 0.2f * unit(rng);
      const float tint[3] = {unit(rng), unit(rng), unit(rng)};
      for (const auto& c : kCorners) {
        positions_.insert(positions_.end(), {x + c[0] * half_w, y + c[1] * half_h, z, 1.f});
        corners_.insert(corners_.end(), {c[0], c[1]});
        tints_.insert(tints_.end(), tint, tint + 3);
      }
    }
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, positions_.data());
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 0, corners_.data());
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 0, tints_.data());
    for (GLuint a = 0; a < 3; ++a) glEnableVertexAttribArray(a);
  }

  using Image = ColourAndDepth;
  // `per_draw` vertices a draw (6: a sprite; 3: a triangle) or all at once (0).
  Image draw(int per_draw) {
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const int count = kSprites * 6;
    for (int first = 0; first < count; first += per_draw ? per_draw : count)
      glDrawArrays(GL_TRIANGLES, first, per_draw ? per_draw : count);
    return read_colour_and_depth();
  }

  static constexpr int kSprites = 400;
  std::vector<GLfloat> positions_, corners_, tints_;
};

TEST_F(RectanglePairsTest, SpritesGiveThePixelsOfTheirTriangles) {
  const Image per_triangle = draw(3), per_sprite = draw(6), at_once = draw(0);
  EXPECT_EQ(per_sprite.colour, per_triangle.colour);
  EXPECT_EQ(per_sprite.depth, per_triangle.depth);
  EXPECT_EQ(at_once.colour, per_triangle.colour);
  EXPECT_EQ(at_once.depth, per_triangle.depth);
  int drawn = 0;
  for (size_t i = 0; i < at_once.colour.size(); i += 4) drawn += at_once.colour[i + 3] == 255;
  EXPECT_GT(drawn, width() * height() / 2);
}

}  // namespace
}  // namespace pineda::test
