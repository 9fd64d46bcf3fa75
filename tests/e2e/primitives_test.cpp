// Culling and front face, polygon modes, points and lines.
#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class PrimitivesTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glColor3f(1, 1, 1);
  }
  // A square with counter-clockwise (ccw) or clockwise winding in window space.
  void square(bool ccw, float x0 = 2, float y0 = 2, float x1 = 10, float y1 = 10) {
    glBegin(GL_QUADS);
    glVertex2f(x0, y0);
    if (ccw) {
      glVertex2f(x1, y0);
      glVertex2f(x1, y1);
      glVertex2f(x0, y1);
    } else {
      glVertex2f(x0, y1);
      glVertex2f(x1, y1);
      glVertex2f(x1, y0);
    }
    glEnd();
  }
  bool lit(int x, int y) { return pixel(x, y)[0] == 255; }
};

TEST_F(PrimitivesTest, CullFaceAndFrontFace) {
  struct Case {
    GLenum front, cull;
    bool ccw_drawn, cw_drawn;
  };
  const Case cases[] = {{GL_CCW, GL_BACK, true, false},  {GL_CCW, GL_FRONT, false, true},
                        {GL_CW, GL_BACK, false, true},   {GL_CW, GL_FRONT, true, false},
                        {GL_CCW, GL_FRONT_AND_BACK, false, false}};
  glEnable(GL_CULL_FACE);
  for (const Case& c : cases) {
    glFrontFace(c.front);
    glCullFace(c.cull);
    clear_to(0, 0, 0, 0);
    square(true);
    EXPECT_EQ(lit(5, 5), c.ccw_drawn) << std::hex << c.front << " " << c.cull;
    clear_to(0, 0, 0, 0);
    square(false);
    EXPECT_EQ(lit(5, 5), c.cw_drawn) << std::hex << c.front << " " << c.cull;
  }
  glDisable(GL_CULL_FACE);
  clear_to(0, 0, 0, 0);
  square(false);
  EXPECT_TRUE(lit(5, 5));
}

TEST_F(PrimitivesTest, CullingDoesNotApplyToLinesAndPoints) {
  glEnable(GL_CULL_FACE);
  glCullFace(GL_FRONT_AND_BACK);
  glBegin(GL_POINTS);
  glVertex2f(5.5f, 5.5f);
  glEnd();
  EXPECT_TRUE(lit(5, 5));
}

TEST_F(PrimitivesTest, PolygonModeLineDrawsTheOutlineOnly) {
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  square(true, 2.5f, 2.5f, 12.5f, 12.5f);  // edges through pixel centres
  EXPECT_FALSE(lit(7, 7));
  EXPECT_FALSE(lit(4, 4));
  EXPECT_TRUE(lit(7, 2));   // bottom edge
  EXPECT_TRUE(lit(7, 12));  // top edge
  EXPECT_TRUE(lit(2, 7));   // left edge
  EXPECT_TRUE(lit(12, 7));  // right edge
  EXPECT_FALSE(lit(7, 1));
  EXPECT_FALSE(lit(7, 13));
  EXPECT_FALSE(lit(1, 7));
  EXPECT_FALSE(lit(13, 7));
}

TEST_F(PrimitivesTest, PolygonModePerFace) {
  glPolygonMode(GL_FRONT, GL_FILL);
  glPolygonMode(GL_BACK, GL_LINE);
  square(false, 2.5f, 2.5f, 12.5f, 12.5f);  // back-facing: outline
  EXPECT_FALSE(lit(7, 7));
  EXPECT_TRUE(lit(7, 2));
  clear_to(0, 0, 0, 0);
  square(true, 2.5f, 2.5f, 12.5f, 12.5f);  // front-facing: filled
  EXPECT_TRUE(lit(7, 7));
}

TEST_F(PrimitivesTest, PolygonModePointDrawsTheVertices) {
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  square(true, 2.5f, 2.5f, 12.5f, 12.5f);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 4);
  EXPECT_TRUE(lit(2, 2));
  EXPECT_TRUE(lit(12, 2));
  EXPECT_TRUE(lit(12, 12));
  EXPECT_TRUE(lit(2, 12));
}

TEST_F(PrimitivesTest, PointsOfSizeOneAndThree) {
  glBegin(GL_POINTS);
  glVertex2f(5.5f, 5.5f);
  glVertex2f(20.3f, 9.7f);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 2);
  EXPECT_TRUE(lit(5, 5));
  EXPECT_TRUE(lit(20, 9));
  clear_to(0, 0, 0, 0);
  glPointSize(3);
  glBegin(GL_POINTS);
  glVertex2f(10.5f, 10.5f);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 9);
  EXPECT_TRUE(lit(9, 9));
  EXPECT_TRUE(lit(11, 11));
  EXPECT_FALSE(lit(12, 10));
  // An even size is centred on the pixel corner nearest the vertex.
  clear_to(0, 0, 0, 0);
  glPointSize(2);
  glBegin(GL_POINTS);
  glVertex2f(20.f, 20.f);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 4);
  EXPECT_TRUE(lit(19, 19));
  EXPECT_TRUE(lit(20, 20));
}

TEST_F(PrimitivesTest, HorizontalAndVerticalLines) {
  glBegin(GL_LINES);
  glVertex2f(2, 5.5f);
  glVertex2f(12, 5.5f);
  glVertex2f(20.5f, 3);
  glVertex2f(20.5f, 9);
  glEnd();
  // Diamond exit: pixels 2..11 of row 5, and 3..8 of column 20.
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 10 + 6);
  EXPECT_TRUE(lit(2, 5));
  EXPECT_TRUE(lit(11, 5));
  EXPECT_FALSE(lit(12, 5));
  EXPECT_FALSE(lit(1, 5));
  EXPECT_TRUE(lit(20, 3));
  EXPECT_TRUE(lit(20, 8));
  EXPECT_FALSE(lit(20, 9));
}

TEST_F(PrimitivesTest, DiagonalLineHasOnePixelPerColumn) {
  glBegin(GL_LINES);
  glVertex2f(0.5f, 0.5f);
  glVertex2f(16.5f, 8.5f);  // x-major
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 16);
  for (int x = 0; x < 16; ++x) {
    int in_column = 0;
    for (int y = 0; y < 12; ++y) in_column += lit(x, y);
    EXPECT_EQ(in_column, 1) << x;
  }
}

TEST_F(PrimitivesTest, LineStripAndLoopShareVerticesOnce) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor4ub(100, 0, 0, 0);
  glBegin(GL_LINE_STRIP);
  glVertex2f(2, 4.5f);
  glVertex2f(10, 4.5f);
  glVertex2f(18, 4.5f);
  glEnd();
  // Half-open segments: the joint pixel is drawn by one segment only.
  EXPECT_EQ(count_pixels({100, 0, 0, 0}), 16);
  clear_to(0, 0, 0, 0);
  glBegin(GL_LINE_LOOP);
  glVertex2f(2.5f, 2.5f);
  glVertex2f(12.5f, 2.5f);
  glVertex2f(12.5f, 12.5f);
  glVertex2f(2.5f, 12.5f);
  glEnd();
  // A closed square outline: 40 pixels, none drawn twice.
  EXPECT_EQ(count_pixels({100, 0, 0, 0}), 40);
}

TEST_F(PrimitivesTest, WideLine) {
  glLineWidth(3);
  glBegin(GL_LINES);
  glVertex2f(2, 10.5f);
  glVertex2f(12, 10.5f);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 10 * 3);
  EXPECT_TRUE(lit(5, 9));
  EXPECT_TRUE(lit(5, 11));
  EXPECT_FALSE(lit(5, 12));
}

// A line exactly on a pixel boundary takes the pixels below (left of) it, and a wide line
// the pixels whose centres lie in [centre - width/2, centre + width/2): llvmpipe's choice.
TEST_F(PrimitivesTest, LinesOnPixelBoundariesTakeTheLowerSide) {
  for (float width : {1.0f, 2.0f, 3.0f}) {
    clear_to(0, 0, 0, 0);
    glLineWidth(width);
    glBegin(GL_LINES);
    glVertex2f(20, 3);
    glVertex2f(20, 9);  // vertical, on the boundary between columns 19 and 20
    glVertex2f(2, 14);
    glVertex2f(12, 14);  // horizontal, between rows 13 and 14
    glEnd();
    const int w = static_cast<int>(width);
    const int first = -((w + 1) / 2);  // offset of the first column (row) from the boundary
    EXPECT_EQ(count_pixels({255, 255, 255, 255}), 6 * w + 10 * w) << width;
    EXPECT_TRUE(lit(20 + first, 5)) << width;
    EXPECT_FALSE(lit(20 + first - 1, 5)) << width;
    EXPECT_TRUE(lit(20 + first + w - 1, 5)) << width;
    EXPECT_FALSE(lit(20 + first + w, 5)) << width;
    EXPECT_TRUE(lit(6, 14 + first)) << width;
    EXPECT_FALSE(lit(6, 14 + first - 1)) << width;
    EXPECT_TRUE(lit(6, 14 + first + w - 1)) << width;
    EXPECT_FALSE(lit(6, 14 + first + w)) << width;
  }
}

TEST_F(PrimitivesTest, StripsAndFans) {
  glBegin(GL_TRIANGLE_STRIP);
  glVertex2i(0, 0);
  glVertex2i(0, 4);
  glVertex2i(4, 0);
  glVertex2i(4, 4);
  glVertex2i(8, 0);
  glVertex2i(8, 4);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 32);
  clear_to(0, 0, 0, 0);
  glBegin(GL_TRIANGLE_FAN);
  glVertex2i(10, 10);
  glVertex2i(14, 10);
  glVertex2i(14, 14);
  glVertex2i(10, 14);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 16);
  clear_to(0, 0, 0, 0);
  glBegin(GL_QUAD_STRIP);
  glVertex2i(0, 0);
  glVertex2i(0, 3);
  glVertex2i(3, 0);
  glVertex2i(3, 3);
  glVertex2i(6, 0);
  glVertex2i(6, 3);
  glEnd();
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 18);
}

TEST_F(PrimitivesTest, IncompletePrimitivesDrawNothing) {
  glBegin(GL_TRIANGLES);
  glVertex2i(0, 0);
  glVertex2i(10, 0);
  glEnd();
  glBegin(GL_QUADS);
  glVertex2i(0, 0);
  glVertex2i(10, 0);
  glVertex2i(10, 10);
  glEnd();
  glBegin(GL_LINES);
  glVertex2i(0, 0);
  glEnd();
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// GL 1.1 2.6.2: in GL_LINE mode, an edge whose starting vertex has the edge flag false is
// not drawn.
TEST_F(PrimitivesTest, EdgeFlagsHideEdgesInLineMode) {
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  glBegin(GL_QUADS);
  glEdgeFlag(GL_TRUE);
  glVertex2f(2.5f, 2.5f);  // bottom edge: drawn
  glEdgeFlag(GL_FALSE);
  glVertex2f(12.5f, 2.5f);  // right edge: hidden
  glEdgeFlag(GL_TRUE);
  glVertex2f(12.5f, 12.5f);  // top edge: drawn
  glEdgeFlag(GL_FALSE);
  glVertex2f(2.5f, 12.5f);  // left edge: hidden
  glEnd();
  EXPECT_TRUE(lit(7, 2));
  EXPECT_TRUE(lit(7, 12));
  EXPECT_FALSE(lit(12, 7));
  EXPECT_FALSE(lit(2, 7));
}

TEST_F(PrimitivesTest, EdgeFlagsHideVerticesInPointMode) {
  glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
  glBegin(GL_TRIANGLES);
  glEdgeFlag(GL_FALSE);
  glVertex2f(2.5f, 2.5f);
  glEdgeFlag(GL_TRUE);
  glVertex2f(12.5f, 2.5f);
  glVertex2f(2.5f, 12.5f);
  glEnd();
  EXPECT_FALSE(lit(2, 2));
  EXPECT_TRUE(lit(12, 2));
  EXPECT_TRUE(lit(2, 12));
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(PrimitivesTest, EdgeFlagArrayEqualsImmediateEdgeFlags) {
  glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
  const GLfloat vertices[] = {2.5f, 2.5f, 12.5f, 2.5f, 12.5f, 12.5f, 2.5f, 12.5f};
  struct Flag {
    GLboolean flag;
    GLubyte padding[3];
  };
  const Flag flags[4] = {{GL_TRUE, {}}, {GL_FALSE, {}}, {GL_TRUE, {}}, {GL_FALSE, {}}};
  glBegin(GL_QUADS);
  for (int i = 0; i < 4; ++i) {
    glEdgeFlag(flags[i].flag);
    glVertex2fv(vertices + 2 * i);
  }
  glEnd();
  glEdgeFlag(GL_TRUE);
  const auto reference = read_all();
  EXPECT_FALSE(lit(12, 7));
  clear_to(0, 0, 0, 0);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_EDGE_FLAG_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, vertices);
  glEdgeFlagPointer(sizeof(Flag), &flags[0].flag);
  glDrawArrays(GL_QUADS, 0, 4);
  EXPECT_EQ(read_all(), reference);
  GLboolean current = GL_FALSE;
  glGetBooleanv(GL_EDGE_FLAG, &current);
  EXPECT_EQ(current, GL_TRUE);  // DrawArrays leaves the current edge flag alone
}

}  // namespace
}  // namespace pineda::test
