// Flat-coloured rectangles and triangles cover exactly the pixels whose centres are inside.
#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class FlatRectTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
  }
};

TEST_F(FlatRectTest, PixelAlignedRectCoversExactlyItsPixels) {
  glColor3f(1, 0, 0);
  glRecti(2, 3, 7, 9);
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 5 * 6);
  EXPECT_TRUE(near_rgba(pixel(2, 3), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(6, 8), {255, 0, 0, 255}));
  EXPECT_TRUE(near_rgba(pixel(7, 8), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(6, 9), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(1, 3), {0, 0, 0, 0}));
  EXPECT_TRUE(near_rgba(pixel(2, 2), {0, 0, 0, 0}));
  expect_osmesa_buffer_matches_readback();
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(FlatRectTest, AdjacentRectsShareNoPixelAndLeaveNoGap) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);  // a pixel drawn twice would be brighter
  glColor4ub(0, 100, 0, 0);
  glRectf(0, 0, 10.5f, 16);
  glRectf(10.5f, 0, 20, 16);
  EXPECT_EQ(count_pixels({0, 100, 0, 0}), 20 * 16);
}

TEST_F(FlatRectTest, TriangleCoversPixelCentresInside) {
  glColor3ub(0, 255, 0);
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(8.5f, 0);
  glVertex2f(0, 8.5f);
  glEnd();
  // Centres (x + .5, y + .5) with x + y + 1 < 8.5: x + y <= 7.
  int expected = 0;
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) {
      const bool inside = x + y <= 7;
      expected += inside;
      EXPECT_TRUE(near_rgba(pixel(x, y), inside ? Rgba{0, 255, 0, 255} : Rgba{0, 0, 0, 0})) << x << "," << y;
    }
  EXPECT_EQ(count_pixels({0, 255, 0, 255}), expected);
}

TEST_F(FlatRectTest, SharedDiagonalEdgeDrawsEachPixelOnce) {
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor4ub(0, 0, 100, 0);
  // Two triangles sharing the diagonal through pixel centres.
  glBegin(GL_TRIANGLES);
  glVertex2f(0, 0);
  glVertex2f(16, 0);
  glVertex2f(16, 16);
  glVertex2f(0, 0);
  glVertex2f(16, 16);
  glVertex2f(0, 16);
  glEnd();
  EXPECT_EQ(count_pixels({0, 0, 100, 0}), 16 * 16);
}

TEST_F(FlatRectTest, FlatShadingUsesTheLastVertexColour) {
  glShadeModel(GL_FLAT);
  glBegin(GL_TRIANGLES);
  glColor3f(1, 0, 0);
  glVertex2f(0, 0);
  glColor3f(0, 1, 0);
  glVertex2f(16, 0);
  glColor3f(0, 0, 1);
  glVertex2f(0, 16);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(1, 1), {0, 0, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(10, 2), {0, 0, 255, 255}));
}

TEST_F(FlatRectTest, QuadsAndPolygonsFill) {
  glColor3f(1, 1, 0);
  glBegin(GL_QUADS);
  glVertex2i(0, 0);
  glVertex2i(4, 0);
  glVertex2i(4, 4);
  glVertex2i(0, 4);
  glEnd();
  glBegin(GL_POLYGON);
  glVertex2i(10, 10);
  glVertex2i(14, 10);
  glVertex2i(17, 12);
  glVertex2i(14, 14);
  glVertex2i(10, 14);
  glEnd();
  // The pentagon: a 4x4 square plus the triangle (14,10)-(17,12)-(14,14), whose inside holds
  // the centres x = 14.5 (y = 10.5 .. 13.5) and x = 15.5 (y = 11.5, 12.5).
  EXPECT_EQ(count_pixels({255, 255, 0, 255}), 16 + 16 + 6);
}

TEST_F(FlatRectTest, ViewportMapsNdcToItsRectangle) {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glViewport(8, 4, 10, 6);
  glColor3f(1, 1, 1);
  glRectf(-1, -1, 1, 1);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 10 * 6);
  EXPECT_TRUE(near_rgba(pixel(8, 4), {255, 255, 255, 255}));
  EXPECT_TRUE(near_rgba(pixel(17, 9), {255, 255, 255, 255}));
}

TEST_F(FlatRectTest, ScissorClipsDrawing) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(4, 4, 3, 2);
  glColor3f(1, 1, 1);
  glRecti(0, 0, 32, 32);
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 6);
}

TEST_F(FlatRectTest, ColorMaskAppliesToDrawing) {
  clear_to(0, 0, 0, 0);
  glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
  glColor4f(1, 1, 1, 1);
  glRecti(0, 0, 4, 4);
  EXPECT_EQ(count_pixels({0, 255, 0, 255}), 16);
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// GL 1.1 Table 2.8: the provoking vertex of flat shading per primitive type.
TEST_F(FlatRectTest, FlatShadingProvokingVertexPerPrimitive) {
  glShadeModel(GL_FLAT);
  const GLubyte colours[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 0}};
  const int square[4][2] = {{0, 0}, {8, 0}, {8, 8}, {0, 8}};
  struct Case {
    GLenum mode;
    int provoking;
  };
  for (const Case& c : {Case{GL_POLYGON, 0}, Case{GL_QUADS, 3}, Case{GL_QUAD_STRIP, 3}}) {
    clear_to(0, 0, 0, 0);
    glBegin(c.mode);
    // Quad strips take their vertices in zig-zag order: 0, 3, 1, 2 of the square.
    const int order_strip[4] = {0, 3, 1, 2}, order_plain[4] = {0, 1, 2, 3};
    const int* order = c.mode == GL_QUAD_STRIP ? order_strip : order_plain;
    for (int i = 0; i < 4; ++i) {
      glColor3ubv(colours[i]);
      glVertex2iv(square[order[i]]);
    }
    glEnd();
    const GLubyte* e = colours[c.provoking];  // index in submission order
    EXPECT_TRUE(near_rgba(pixel(4, 4), {e[0], e[1], e[2], 255})) << std::hex << c.mode;
  }
}

}  // namespace
}  // namespace pineda::test
