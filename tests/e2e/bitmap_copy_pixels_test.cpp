// glBitmap (position, origin, advance, unpack state, fragment operations) and glCopyPixels
// (colour, depth, stencil, overlapping rectangles, zoom, pixel transfer).
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class BitmapTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    clear_to(0, 0, 0, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }
  std::array<float, 4> position() {
    std::array<float, 4> p{};
    glGetFloatv(GL_CURRENT_RASTER_POSITION, p.data());
    return p;
  }
};

constexpr Rgba kBlack{0, 0, 0, 0};

TEST_F(BitmapTest, SetBitsTakeTheRasterColour) {
  const GLubyte bits[2] = {0xc1, 0x80};  // row 0: 1100 0001, row 1: 1000 0000
  glColor4f(1, 0.5f, 0, 1);
  glWindowPos2i(4, 4);
  glColor3f(0, 0, 1);  // after the raster position: not used
  glBitmap(8, 2, 0, 0, 10, 1, bits);
  const Rgba orange{255, 128, 0, 255};
  EXPECT_EQ(pixel(4, 4), orange);
  EXPECT_EQ(pixel(5, 4), orange);
  EXPECT_EQ(pixel(6, 4), kBlack);
  EXPECT_EQ(pixel(11, 4), orange);
  EXPECT_EQ(pixel(4, 5), orange);
  EXPECT_EQ(pixel(5, 5), kBlack);
  EXPECT_EQ(count_pixels(orange), 4);
  EXPECT_EQ(position(), (std::array<float, 4>{14, 5, 0, 1}));
}

TEST_F(BitmapTest, OriginLsbFirstAndSkips) {
  const GLubyte bits[2] = {0x00, 0x02};  // LSB first: second row, bit 1
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glColor3f(1, 1, 1);
  glWindowPos2f(10.5f, 10.f);
  glBitmap(8, 1, 2.f, 1.f, 0, 0, bits);  // lower-left at floor(10.5 - 2), 10 - 1
  EXPECT_EQ(pixel(9, 9), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(count_pixels({255, 255, 255, 255}), 1);
  glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
  const GLubyte one = 0x10;  // bit 3 from the left
  glWindowPos2i(0, 0);
  glBitmap(1, 1, 0, 0, 0, 0, &one);
  EXPECT_EQ(pixel(0, 0), (Rgba{255, 255, 255, 255}));
}

TEST_F(BitmapTest, AlignmentPadsRows) {
  const GLubyte bits[8] = {0x80, 0, 0, 0, 0x40, 0, 0, 0};
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glColor3f(0, 1, 0);
  glWindowPos2i(0, 0);
  glBitmap(3, 2, 0, 0, 0, 0, bits);
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(pixel(1, 1), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(count_pixels({0, 255, 0, 255}), 2);
}

TEST_F(BitmapTest, NullBitmapAndInvalidPosition) {
  glWindowPos2i(1, 1);
  glBitmap(0, 0, 0, 0, 3.5f, -1.f, nullptr);
  EXPECT_EQ(position(), (std::array<float, 4>{4.5f, 0, 0, 1}));
  glRasterPos2f(5.f, 0.f);  // invalid: no drawing and no advance
  const GLubyte all = 0xff;
  glBitmap(8, 1, 0, 0, 3, 3, &all);
  GLboolean valid = GL_TRUE;
  glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
  EXPECT_EQ(valid, GL_FALSE);
  EXPECT_EQ(count_pixels(kBlack), width() * height());
  glBitmap(-1, 1, 0, 0, 0, 0, &all);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
}

TEST_F(BitmapTest, FragmentsUseRasterDepthAndStencil) {
  glClearDepth(0.5);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 3, 0xff);
  glStencilOp(GL_KEEP, GL_INCR, GL_REPLACE);
  const GLubyte bits = 0xc0;
  glColor3f(1, 1, 1);
  glWindowPos3f(0, 0, 0.25f);  // in front: passes
  glBitmap(2, 1, 0, 0, 0, 0, &bits);
  glWindowPos3f(0, 1, 0.75f);  // behind: fails
  glBitmap(2, 1, 0, 0, 0, 0, &bits);
  EXPECT_EQ(pixel(0, 0), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(pixel(0, 1), kBlack);
  GLubyte s[2] = {};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, 1, 2, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  EXPECT_EQ(s[0], 3);
  EXPECT_EQ(s[1], 1);
}

// On a pipeline that changes nothing but for the depth test, runs of set bits are written straight
// into the colour buffer (PixelFragmentWriter::rgba8_row); an alpha test that passes everything
// sends the bitmap down the per-fragment path. Positions partly and wholly outside the window,
// LSB_FIRST, skips, scissor and depth test give the same frames both ways.
TEST_F(BitmapTest, RunsOnAPlainPipelineMatchTheFragmentPath) {
  std::vector<GLubyte> bits(5 * 21);  // 37 x 21 bits, rows of 5 bytes
  for (size_t i = 0; i < bits.size(); ++i) bits[i] = GLubyte(i * 89 + 0x35);
  const int positions[][2] = {{3, 4}, {-20, 9}, {25, 28}, {-40, 2}, {40, 40}};
  glAlphaFunc(GL_ALWAYS, 0.f);
  for (const auto& at : positions)
    for (const bool lsb_first : {false, true})
      for (const bool scissor : {false, true})
        for (const bool depth_test : {false, true}) {
          std::vector<uint8_t> frames[2];
          for (int pass = 0; pass < 2; ++pass) {
            clear_to(0.1f, 0.2f, 0.3f, 0.4f);
            clear_depth_halves(0.1, 0.5);
            if (pass == 1) glEnable(GL_ALPHA_TEST);
            if (scissor) glEnable(GL_SCISSOR_TEST);
            if (depth_test) glEnable(GL_DEPTH_TEST);
            glScissor(2, 3, 21, 19);
            glPixelStorei(GL_UNPACK_LSB_FIRST, lsb_first ? GL_TRUE : GL_FALSE);
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, 40);
            glColor4f(0.9f, 0.6f, 0.3f, 0.7f);  // halfway values: rounding matters
            glWindowPos3f(float(at[0]), float(at[1]), 0.25f);
            glBitmap(35, 21, 0.f, 0.f, 0.f, 0.f, bits.data());
            glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
            glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
            glDisable(GL_ALPHA_TEST);
            glDisable(GL_SCISSOR_TEST);
            glDisable(GL_DEPTH_TEST);
            ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
            frames[pass] = read_all();
          }
          EXPECT_EQ(frames[0], frames[1]) << "at " << at[0] << "," << at[1] << " lsb first " << lsb_first << " scissor "
                                          << scissor << " depth test " << depth_test;
        }
  // Pinned: at (3, 4), MSB first, every set bit inside the window and nothing else.
  clear_to(0, 0, 0, 0);
  glColor4f(1, 0, 1, 1);
  glWindowPos2i(3, 4);
  glBitmap(35, 21, 0.f, 0.f, 0.f, 0.f, bits.data());
  int set = 0;
  for (int j = 0; j < 21; ++j)
    for (int i = 0; i < 35; ++i) set += 3 + i < width() && 4 + j < height() && (bits[size_t(j) * 5 + i / 8] >> (7 - i % 8)) & 1;
  EXPECT_GT(set, 100);
  EXPECT_EQ(count_pixels({255, 0, 255, 255}), set);
}

TEST_F(BitmapTest, CompiledIntoAList) {
  GLubyte bits = 0x80;
  glColor3f(1, 0, 0);
  glNewList(1, GL_COMPILE);
  glWindowPos2i(2, 2);
  glBitmap(1, 1, 0, 0, 1, 0, &bits);
  glBitmap(1, 1, 0, 0, 1, 0, &bits);
  glEndList();
  bits = 0;
  glCallList(1);
  EXPECT_EQ(pixel(2, 2), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(pixel(3, 2), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 2);
}

class CopyPixelsTest : public BitmapTest {};

TEST_F(CopyPixelsTest, CopiesColourToTheRasterPosition) {
  const GLubyte image[2][2][4] = {{{255, 0, 0, 255}, {0, 255, 0, 255}}, {{0, 0, 255, 255}, {9, 9, 9, 9}}};
  glWindowPos2i(1, 1);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glWindowPos2i(10, 20);
  glCopyPixels(1, 1, 2, 2, GL_COLOR);
  EXPECT_EQ(pixel(10, 20), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(pixel(11, 20), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(pixel(10, 21), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(pixel(11, 21), (Rgba{9, 9, 9, 9}));
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(CopyPixelsTest, OverlappingRectanglesReadTheSourceFirst) {
  std::vector<GLubyte> row(8 * 4);
  for (int i = 0; i < 8; ++i) row[4 * i] = GLubyte(10 * (i + 1)), row[4 * i + 3] = 255;
  glWindowPos2i(0, 0);
  glDrawPixels(8, 1, GL_RGBA, GL_UNSIGNED_BYTE, row.data());
  glWindowPos2i(1, 0);
  glCopyPixels(0, 0, 8, 1, GL_COLOR);  // shift right by one
  for (int i = 0; i < 8; ++i) EXPECT_EQ(pixel(i + 1, 0)[0], 10 * (i + 1)) << i;
  EXPECT_EQ(pixel(0, 0)[0], 10);
}

// A copy at a y zoom of 1 from inside the buffer reads its rows as it draws them, from the top
// when it moves up: every shift (up, down, none; left, right, mirrored) gives the source's
// original pixels, on the direct rows and on the per-fragment path.
TEST_F(CopyPixelsTest, OverlappingCopiesAtZoomOneMoveTheOriginalPixels) {
  const int w = width(), h = height();
  std::vector<GLubyte> image(size_t(w) * h * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = GLubyte(i * 31 + (i >> 7) * 5);
  const int x0 = 4, y0 = 5, cw = 17, ch = 13;
  glAlphaFunc(GL_ALWAYS, 0.f);
  for (int per_fragment = 0; per_fragment < 2; ++per_fragment)
    for (const float zoom_x : {1.f, -1.f})
      for (int dy = -2; dy <= 2; dy += 2)
        for (int dx = -3; dx <= 3; dx += 3) {
          glPixelZoom(1, 1);
          glWindowPos2i(0, 0);
          glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
          if (per_fragment) glEnable(GL_ALPHA_TEST);
          glPixelZoom(zoom_x, 1);
          // (Mirrored: the image extends to the left of the raster position.)
          const int to_x = x0 + dx + (zoom_x < 0 ? cw : 0), to_y = y0 + dy;
          glWindowPos2i(to_x, to_y);
          glCopyPixels(x0, y0, cw, ch, GL_COLOR);
          glDisable(GL_ALPHA_TEST);
          ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
          const std::vector<uint8_t> frame = read_all();
          for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
              const int i = x - (x0 + dx), j = y - to_y;
              const bool copied = i >= 0 && i < cw && j >= 0 && j < ch;
              const int sx = copied ? x0 + (zoom_x < 0 ? cw - 1 - i : i) : x, sy = copied ? y0 + j : y;
              for (int c = 0; c < 4; ++c)
                ASSERT_EQ(frame[(size_t(y) * w + x) * 4 + c], image[(size_t(sy) * w + sx) * 4 + c])
                    << "per fragment " << per_fragment << " zoom " << zoom_x << " shift " << dx << "," << dy << " at "
                    << x << "," << y << " component " << c;
            }
        }
  glPixelZoom(1, 1);
}

TEST_F(CopyPixelsTest, ZoomScissorAndTransfer) {
  const GLubyte c[4] = {100, 0, 0, 255};
  glWindowPos2i(0, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, c);
  glPixelZoom(2, 2);
  glPixelTransferf(GL_GREEN_BIAS, 1.f);
  glWindowPos2i(4, 4);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, 5, 32);
  glCopyPixels(0, 0, 1, 1, GL_COLOR);
  glPixelTransferf(GL_GREEN_BIAS, 0.f);
  EXPECT_EQ(count_pixels({100, 255, 0, 255}), 2);  // x = 4 only, rows 4 and 5
}

// Without pixel transfer the copied colour stays bytes (PixelRectImage::rgba8) and, on a
// pipeline that changes nothing but for the depth test, is written straight into the colour
// buffer; an alpha test that passes everything sends it down the per-fragment path. Overlapping
// and partly outside source rectangles, zooms, scissor and depth test give the same frames both ways.
TEST_F(CopyPixelsTest, ColourCopiesOnAPlainPipelineMatchTheFragmentPath) {
  const int w = width(), h = height();
  std::vector<GLubyte> image(size_t(w) * h * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = GLubyte(i * 29 + (i >> 6) * 3);
  const float zooms[][2] = {{1, 1}, {2, 3}, {-1, 1}, {0.5f, -2}};
  struct Copy {
    int x, y, width, height, to_x, to_y;
  };
  const Copy copies[] = {{0, 0, 20, 10, 3, 5}, {-2, 8, 30, 30, 12, 12}, {10, 10, 8, 8, 12, 14}};
  glAlphaFunc(GL_ALWAYS, 0.f);
  for (const auto& zoom : zooms)
    for (const Copy& c : copies)
      for (const bool scissor : {false, true})
        for (const bool depth_test : {false, true}) {
          std::vector<uint8_t> frames[2];
          for (int pass = 0; pass < 2; ++pass) {
            glClearDepth(0.5);
            glClear(GL_DEPTH_BUFFER_BIT);
            glPixelZoom(1, 1);
            glWindowPos2i(0, 0);
            glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
            if (pass == 1) glEnable(GL_ALPHA_TEST);
            if (scissor) glEnable(GL_SCISSOR_TEST);
            if (depth_test) glEnable(GL_DEPTH_TEST);
            glScissor(2, 4, 17, 21);
            glPixelZoom(zoom[0], zoom[1]);
            glWindowPos3f(float(c.to_x), float(c.to_y), c.to_x > 5 ? 0.75f : 0.25f);
            glCopyPixels(c.x, c.y, c.width, c.height, GL_COLOR);
            glDisable(GL_ALPHA_TEST);
            glDisable(GL_SCISSOR_TEST);
            glDisable(GL_DEPTH_TEST);
            ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
            frames[pass] = read_all();
          }
          EXPECT_EQ(frames[0], frames[1]) << "zoom " << zoom[0] << "x" << zoom[1] << " copy from " << c.x << ","
                                          << c.y << " scissor " << scissor << " depth test " << depth_test;
          if (!depth_test || c.to_x <= 5) {
            EXPECT_NE(frames[0], image);  // something was copied (at depth 0.25 over 0.5 when tested)
          }
        }
}

TEST_F(CopyPixelsTest, DepthAndStencil) {
  glClearDepth(0.25);
  glClearStencil(7);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glScissor(0, 0, 1, 1);
  glEnable(GL_SCISSOR_TEST);
  glClearDepth(0.75);
  glClearStencil(9);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glWindowPos2i(5, 5);
  glCopyPixels(0, 0, 1, 1, GL_DEPTH);
  glCopyPixels(0, 0, 1, 1, GL_STENCIL);
  GLuint z = 0;
  glReadPixels(5, 5, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z);
  EXPECT_EQ(z >> 8, uint32_t(0.75 * 16777215 + 0.5));
  GLubyte s = 0;
  glReadPixels(5, 5, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  EXPECT_EQ(s, 9);
  glReadPixels(6, 5, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
  EXPECT_EQ(s, 7);
}

// GL_DEPTH_STENCIL (EXT_packed_depth_stencil; piglit depthstencil-default_fb-copypixels)
// copies both: depth through the fragment's depth, stencil written as GL_STENCIL writes it
// (not by the stencil test's operation).
TEST_F(CopyPixelsTest, DepthStencilCopiesBoth) {
  glClearDepth(0.25);
  glClearStencil(7);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glScissor(0, 0, 2, 1);
  glEnable(GL_SCISSOR_TEST);
  glClearDepth(0.75);
  glClearStencil(0x33);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0x55, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  glWindowPos2i(5, 5);
  glCopyPixels(0, 0, 2, 1, GL_DEPTH_STENCIL);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  GLuint z[3] = {};
  glReadPixels(5, 5, 3, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z);
  EXPECT_EQ(z[0] >> 8, uint32_t(0.75 * 16777215 + 0.5));
  EXPECT_EQ(z[1] >> 8, uint32_t(0.75 * 16777215 + 0.5));
  EXPECT_EQ(z[2] >> 8, uint32_t(0.25 * 16777215 + 0.5));  // outside the copy
  GLubyte s[3] = {};
  glReadPixels(5, 5, 3, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  EXPECT_EQ(s[0], 0x33);
  EXPECT_EQ(s[1], 0x33);
  EXPECT_EQ(s[2], 7);
}

class CopyPixelsWithoutStencilTest : public BitmapTest {
 protected:
  SurfaceSpec spec() const override { return {8, 8, 24, 0}; }
};

TEST_F(CopyPixelsWithoutStencilTest, DepthStencilNeedsBothBuffers) {
  glCopyPixels(0, 0, 1, 1, GL_DEPTH_STENCIL);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glCopyPixels(0, 0, 1, 1, GL_DEPTH);
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(CopyPixelsTest, Errors) {
  glCopyPixels(0, 0, -1, 1, GL_COLOR);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glCopyPixels(0, 0, 1, 1, GL_RGBA);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glCopyPixels(-100, -100, 1000, 1000, GL_COLOR);  // partly outside: no crash, no error
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
