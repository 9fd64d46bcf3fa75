// Line stipple (GL 1.5 section 3.4.2) and polygon stipple (section 3.5.2): the pattern, its
// repeat factor and counter reset, the window-aligned 32x32 polygon pattern under the pixel
// store state; state, attributes, display lists.
#include <vector>

#include "tests/e2e/support/pixel_test.h"

namespace pineda::test {
namespace {

constexpr Rgba kWhite{255, 255, 255, 255};
constexpr Rgba kBlack{0, 0, 0, 0};

class StippleTest : public PixelTest {
 protected:
  void SetUp() override {
    PixelTest::SetUp();
    glColor3f(1, 1, 1);
  }
  // Which pixels of row y are white, as a string of 0/1 from x = 0.
  std::string row(int y) {
    const std::vector<uint8_t> all = read_all();
    std::string s;
    for (int x = 0; x < width(); ++x) s += all[(size_t(y) * width() + x) * 4] == 255 ? '1' : '0';
    return s;
  }
  void horizontal_line(float x0, float x1, float y) {
    glBegin(GL_LINES);
    glVertex2f(x0, y);
    glVertex2f(x1, y);
    glEnd();
  }
};

TEST_F(StippleTest, LinePatternBitZeroFirst) {
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x00ff);
  horizontal_line(0, 16, 2.5f);
  EXPECT_EQ(row(2), "1111111100000000");
  glLineStipple(1, 0x5555);  // 0101...: bit 0 set
  horizontal_line(0, 16, 4.5f);
  EXPECT_EQ(row(4), "1010101010101010");
}

TEST_F(StippleTest, LinePatternRepeatFactor) {
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(2, 0x0005);  // bits 0 and 2, each for two fragments
  horizontal_line(0, 16, 2.5f);
  EXPECT_EQ(row(2), "1100110000000000");
}

TEST_F(StippleTest, LineCountsFromTheFirstVertex) {
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x000f);
  horizontal_line(16, 0, 2.5f);  // right to left: the pattern starts at the right end
  EXPECT_EQ(row(2), "0000000000001111");
}

TEST_F(StippleTest, StripContinuesIndependentLinesRestart) {
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x00ff);
  glBegin(GL_LINE_STRIP);
  glVertex2f(0, 2.5f);
  glVertex2f(4, 2.5f);
  glVertex2f(16, 2.5f);
  glEnd();
  EXPECT_EQ(row(2), "1111111100000000");
  glBegin(GL_LINES);
  glVertex2f(0, 6.5f);
  glVertex2f(4, 6.5f);
  glVertex2f(4, 6.5f);
  glVertex2f(16, 6.5f);
  glEnd();
  EXPECT_EQ(row(6), "1111111111110000");
}

// Each draw is a strip of its own, even one whose state repeats the previous draw's (drawn
// before anything reads the pixels).
TEST_F(StippleTest, EveryDrawOfAStripStartsThePatternAgain) {
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x00ff);
  const GLfloat strips[] = {0, 2.5f, 4, 2.5f, 12, 2.5f, 0, 6.5f, 16, 6.5f};
  glVertexPointer(2, GL_FLOAT, 0, strips);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawArrays(GL_LINE_STRIP, 0, 3);
  glDrawArrays(GL_LINE_STRIP, 3, 2);
  EXPECT_EQ(row(2), "1111111100000000");
  EXPECT_EQ(row(6), "1111111100000000");
}

TEST_F(StippleTest, LineStippleOffDrawsEverything) {
  glLineStipple(1, 0x0001);
  horizontal_line(0, 16, 2.5f);
  EXPECT_EQ(row(2), "1111111111111111");
}

TEST_F(StippleTest, LineStippleState) {
  GLint v = 0;
  glGetIntegerv(GL_LINE_STIPPLE_PATTERN, &v);
  EXPECT_EQ(v, 0xffff);
  glGetIntegerv(GL_LINE_STIPPLE_REPEAT, &v);
  EXPECT_EQ(v, 1);
  glLineStipple(300, 0x1234);  // the factor is clamped to [1, 256]
  glGetIntegerv(GL_LINE_STIPPLE_REPEAT, &v);
  EXPECT_EQ(v, 256);
  glLineStipple(0, 0x1234);
  glGetIntegerv(GL_LINE_STIPPLE_REPEAT, &v);
  EXPECT_EQ(v, 1);
  glGetIntegerv(GL_LINE_STIPPLE_PATTERN, &v);
  EXPECT_EQ(v, 0x1234);
  glPushAttrib(GL_LINE_BIT);
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(3, 0xff00);
  glPopAttrib();
  EXPECT_FALSE(glIsEnabled(GL_LINE_STIPPLE));
  glGetIntegerv(GL_LINE_STIPPLE_PATTERN, &v);
  EXPECT_EQ(v, 0x1234);
}

// A 160-pixel window maps x = 10.5 just past the pixel centre in float; the pattern still
// starts at that pixel, counted from the snapped vertex that coverage uses (piglit linestipple).
class WideStippleTest : public StippleTest {
 protected:
  SurfaceSpec spec() const override { return {160, 160, 24, 8}; }
};

TEST_F(WideStippleTest, PatternStartsAtTheSnappedFirstVertex) {
  glEnable(GL_LINE_STIPPLE);
  glLineStipple(1, 0x00ff);
  glTranslatef(10, 10, 0);
  glBegin(GL_LINES);
  glVertex2f(0.5f, 2.5f);
  glVertex2f(24.5f, 2.5f);
  glEnd();
  EXPECT_EQ(row(12).substr(8, 30), "001111111100000000111111110000");
  glLineStipple(2, 0x838f);  // factor 2 along a strip: the count goes on at the corner
  glBegin(GL_LINE_STRIP);
  glVertex2f(0.5f, 32.5f);
  glVertex2f(32.5f, 32.5f);
  glVertex2f(32.5f, 33.5f);
  glVertex2f(0.5f, 33.5f);
  glEnd();
  // Fragments 0..31 at x = 10..41 of row 42, 32 at the corner (x = 42), then 33..64 right to
  // left on row 43 from x = 42 down to 11 (x = 10 holds the last vertex: not drawn).
  auto on = [](int fragment) { return (0x838f >> ((fragment / 2) & 15)) & 1 ? '1' : '0'; };
  std::string expected42, expected43 = "0";
  for (int x = 10; x < 42; ++x) expected42 += on(x - 10);
  for (int x = 11; x < 42; ++x) expected43 += on(33 + 42 - x);
  EXPECT_EQ(row(42).substr(10, 32), expected42);
  EXPECT_EQ(row(43).substr(10, 32), expected43);
}

// Rows of 4 bytes each, most significant bit = leftmost pixel.
std::vector<GLubyte> stipple_of(GLubyte even_rows, GLubyte odd_rows) {
  std::vector<GLubyte> s(128);
  for (int y = 0; y < 32; ++y)
    for (int b = 0; b < 4; ++b) s[y * 4 + b] = (y % 2) ? odd_rows : even_rows;
  return s;
}

TEST_F(StippleTest, PolygonPatternIsWindowAligned) {
  const std::vector<GLubyte> pattern = stipple_of(0xaa, 0x55);  // a checkerboard, (0, 0) set
  glPolygonStipple(pattern.data());
  glEnable(GL_POLYGON_STIPPLE);
  full_quad();
  EXPECT_EQ(row(0), "1010101010101010");
  EXPECT_EQ(row(1), "0101010101010101");
  EXPECT_EQ(count_pixels(kWhite), 128);
  // Moving the polygon does not move the pattern.
  glClear(GL_COLOR_BUFFER_BIT);
  glBegin(GL_TRIANGLES);
  glVertex2f(1, 0);
  glVertex2f(17, 0);
  glVertex2f(17, 16);
  glEnd();
  EXPECT_TRUE(near_rgba(pixel(12, 0), kWhite));
  EXPECT_TRUE(near_rgba(pixel(13, 0), kBlack));
}

TEST_F(StippleTest, PolygonStippleSparesLinesAndPoints) {
  const std::vector<GLubyte> none(128, 0);
  glPolygonStipple(none.data());
  glEnable(GL_POLYGON_STIPPLE);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 0);
  horizontal_line(0, 16, 2.5f);
  glBegin(GL_POINTS);
  glVertex2f(5.5f, 9.5f);
  glEnd();
  EXPECT_EQ(count_pixels(kWhite), 17);
}

TEST_F(StippleTest, PolygonStippleUnpackAndPack) {
  std::vector<GLubyte> lsb = stipple_of(0x01, 0x01);  // LSB first: pixel 0 of each byte
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPolygonStipple(lsb.data());
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glEnable(GL_POLYGON_STIPPLE);
  full_quad();
  EXPECT_EQ(row(5), "1000000010000000");
  std::vector<GLubyte> back(128, 0x33);
  glGetPolygonStipple(back.data());
  EXPECT_EQ(back, stipple_of(0x80, 0x80));  // MSB first on the way out
}

TEST_F(StippleTest, PolygonStippleDefaultsToAllSet) {
  std::vector<GLubyte> back(128, 0);
  glGetPolygonStipple(back.data());
  EXPECT_EQ(back, std::vector<GLubyte>(128, 0xff));
  glEnable(GL_POLYGON_STIPPLE);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 256);
}

TEST_F(StippleTest, PolygonStippleAttribAndLists) {
  const std::vector<GLubyte> checker = stipple_of(0xaa, 0x55), none(128, 0);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glPolygonStipple(checker.data());  // read now
  glEndList();
  glPolygonStipple(none.data());
  glPushAttrib(GL_POLYGON_STIPPLE_BIT);
  glCallList(list);
  glEnable(GL_POLYGON_STIPPLE);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 128);
  glPopAttrib();
  glClear(GL_COLOR_BUFFER_BIT);
  full_quad();
  EXPECT_EQ(count_pixels(kWhite), 0);  // pattern restored, enable untouched by this group
  glDeleteLists(list, 1);
}

}  // namespace
}  // namespace pineda::test
