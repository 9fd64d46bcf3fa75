// A flat-shaded line clipped at both ends keeps the colour of its last vertex (the provoking
// one), whichever way it is drawn, at width 1 and 5, smooth or not (piglit line-flat-clip-color,
// which switches its arrays on with glEnable as Mesa's compatibility profile allows).
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class FlatLineClipTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {32, 32, 0, 0}; }
  // The colours of the row where the line lies, or empty when no pixel of the middle rows is lit.
  std::vector<Rgba> lit_row() {
    for (int y = height() / 2 - 1; y <= height() / 2 + 1; ++y) {
      std::vector<Rgba> row;
      for (int x = 0; x < width(); ++x) row.push_back(pixel(x, y));
      if (row[0] != Rgba{0, 0, 0, 255}) return row;
    }
    return {};
  }
};

TEST_F(FlatLineClipTest, ClippedFlatLineHasTheLastVertexColour) {
  static const float verts[2][2] = {{-10, 0}, {10, 0}};  // far outside on both sides
  static const float colors[2][3] = {{1, 0, 0}, {0, 1, 0}};
  glEnable(GL_VERTEX_ARRAY);
  glEnable(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, verts);
  glColorPointer(3, GL_FLOAT, 0, colors);
  glShadeModel(GL_FLAT);
  const GLuint forward[2] = {0, 1}, backward[2] = {1, 0};
  for (float width : {1.f, 5.f})
    for (bool smooth : {false, true}) {
      glLineWidth(width);
      if (smooth) glEnable(GL_LINE_SMOOTH);
      else glDisable(GL_LINE_SMOOTH);
      for (const GLuint* order : {forward, backward}) {
        clear_to(0, 0, 0, 1);
        glDrawElements(GL_LINES, 2, GL_UNSIGNED_INT, order);
        Rgba expected = order == forward ? Rgba{0, 255, 0, 255} : Rgba{255, 0, 0, 255};
        // The line lies on the boundary of rows 15 and 16: smooth at width 1, each row is half
        // covered, and the coverage is the written alpha.
        if (smooth && width == 1.f) expected[3] = 128;
        const std::vector<Rgba> row = lit_row();
        ASSERT_EQ(row.size(), size_t(32)) << "width " << width << " smooth " << smooth;
        for (int x = 0; x < 32; ++x)
          EXPECT_EQ(row[x], expected) << "x " << x << " width " << width << " smooth " << smooth;
      }
    }
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
