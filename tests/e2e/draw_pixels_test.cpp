// glDrawPixels: formats and types, unpack state, zoom, fragment operations, depth and
// stencil images, pixel transfer, display lists and errors.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class DrawPixelsTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    clear_to(0, 0, 0, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  }
  GLenum error() { return glGetError(); }
  uint32_t depth_at(int x, int y) {
    GLuint z = 0;
    glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &z);
    return z >> 8;  // 24-bit buffer
  }
  int stencil_at(int x, int y) {
    GLubyte s = 0;
    glReadPixels(x, y, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, &s);
    return s;
  }
  // That the frame holds a w x h image drawn at (x0, y0) with zoom 1 x zoom_y, component c of
  // its pixel (i, j) being byte_of(i, j, c), over zeros.
  template <typename ByteOf>
  void expect_image_at(int x0, int y0, int w, int h, int zoom_y, ByteOf byte_of, const std::string& what) {
    const std::vector<uint8_t> frame = read_all();
    for (int y = 0; y < height(); ++y)
      for (int x = 0; x < width(); ++x) {
        const int i = x - x0, j = (y - y0) / zoom_y;
        const bool inside = i >= 0 && i < w && y >= y0 && j < h;
        for (int c = 0; c < 4; ++c)
          ASSERT_EQ(frame[(size_t(y) * width() + x) * 4 + c], inside ? byte_of(i, j, c) : 0)
              << what << " at " << x << "," << y << " component " << c;
      }
  }
};

TEST_F(DrawPixelsTest, RgbaImageAtTheRasterPosition) {
  const GLubyte image[2][3][4] = {{{10, 20, 30, 40}, {50, 60, 70, 80}, {90, 100, 110, 120}},
                                  {{1, 2, 3, 4}, {5, 6, 7, 8}, {9, 10, 11, 12}}};
  glWindowPos2i(4, 5);
  glDrawPixels(3, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(pixel(4, 5), (Rgba{10, 20, 30, 40}));
  EXPECT_EQ(pixel(6, 5), (Rgba{90, 100, 110, 120}));
  EXPECT_EQ(pixel(5, 6), (Rgba{5, 6, 7, 8}));
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height() - 6);
}

TEST_F(DrawPixelsTest, FormatsAndTypes) {
  glWindowPos2i(0, 0);
  const GLfloat lum_alpha[2] = {0.2f, 0.6f};
  glDrawPixels(1, 1, GL_LUMINANCE_ALPHA, GL_FLOAT, lum_alpha);
  EXPECT_EQ(pixel(0, 0), (Rgba{51, 51, 51, 153}));
  const GLushort bgr[3] = {0, 65535, 32896};  // B, G, R
  glDrawPixels(1, 1, GL_BGR, GL_UNSIGNED_SHORT, bgr);
  EXPECT_EQ(pixel(0, 0), (Rgba{128, 255, 0, 255}));
  const GLbyte green = 127;
  glDrawPixels(1, 1, GL_GREEN, GL_BYTE, &green);
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 255, 0, 255}));
  const GLuint alpha = 0xffffffffu;
  glDrawPixels(1, 1, GL_ALPHA, GL_UNSIGNED_INT, &alpha);
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 0, 255}));
  const GLubyte bgra[4] = {1, 2, 3, 4};
  glDrawPixels(1, 1, GL_BGRA, GL_UNSIGNED_BYTE, bgra);
  EXPECT_EQ(pixel(0, 0), (Rgba{3, 2, 1, 4}));
  const GLubyte rgb332 = 0xe3;  // R 7/7, G 0, B 3/3
  glDrawPixels(1, 1, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, &rgb332);
  EXPECT_EQ(pixel(0, 0), (Rgba{255, 0, 255, 255}));
  const GLuint rgba8888 = 0x11223344u;  // UNSIGNED_INT_8_8_8_8: R in the high byte
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_INT_8_8_8_8, &rgba8888);
  EXPECT_EQ(pixel(0, 0), (Rgba{0x11, 0x22, 0x33, 0x44}));
}

TEST_F(DrawPixelsTest, UnpackRowLengthSkipsAlignmentAndSwapBytes) {
  // 4x3 RGB bytes, rows padded to 4-byte alignment: 12 bytes per row already aligned; use 3x3.
  GLubyte image[3][12] = {};
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) image[j][i * 3 + c] = GLubyte(100 + 10 * j + i + c);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);  // 9-byte rows padded to 12
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 3);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  glWindowPos2i(0, 0);
  glDrawPixels(2, 2, GL_RGB, GL_UNSIGNED_BYTE, image);
  EXPECT_EQ(pixel(0, 0), (Rgba{111, 112, 113, 255}));
  EXPECT_EQ(pixel(1, 1), (Rgba{122, 123, 124, 255}));
  EXPECT_EQ(pixel(2, 0), (Rgba{0, 0, 0, 0}));
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
  const GLushort red = 0xff00;  // read as 0x00ff
  glDrawPixels(1, 1, GL_RED, GL_UNSIGNED_SHORT, &red);
  EXPECT_EQ(pixel(0, 0), (Rgba{1, 0, 0, 255}));
}

TEST_F(DrawPixelsTest, ZoomReplicatesAndMirrors) {
  const GLubyte image[2][2][4] = {{{255, 0, 0, 255}, {0, 255, 0, 255}}, {{0, 0, 255, 255}, {255, 255, 255, 255}}};
  glPixelZoom(2.f, 3.f);
  glWindowPos2i(2, 2);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
  EXPECT_EQ(count_pixels({255, 0, 0, 255}), 6);
  EXPECT_EQ(pixel(3, 4), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(pixel(4, 4), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(pixel(5, 7), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(pixel(5, 8), (Rgba{0, 0, 0, 0}));
  clear_to(0, 0, 0, 0);
  glPixelZoom(-1.f, -1.f);  // drawn to the left of and below the raster position
  glWindowPos2i(10, 10);
  glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, image);
  EXPECT_EQ(pixel(9, 9), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(pixel(8, 9), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(pixel(9, 8), (Rgba{0, 0, 255, 255}));
  EXPECT_EQ(pixel(8, 8), (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height() - 4);
  clear_to(0, 0, 0, 0);
  glPixelZoom(0.5f, 1.f);  // pixel centres 0.5 and 1.5 pick image columns 1 and 3
  const GLubyte row[4] = {10, 20, 30, 40};
  glWindowPos2i(0, 0);
  glDrawPixels(4, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, row);
  EXPECT_EQ(pixel(0, 0), (Rgba{20, 20, 20, 255}));
  EXPECT_EQ(pixel(1, 0), (Rgba{40, 40, 40, 255}));
  EXPECT_EQ(pixel(2, 0), (Rgba{0, 0, 0, 0}));
  float zoom[2];
  glGetFloatv(GL_ZOOM_X, &zoom[0]);
  glGetFloatv(GL_ZOOM_Y, &zoom[1]);
  EXPECT_EQ(zoom[0], 0.5f);
  EXPECT_EQ(zoom[1], 1.f);
}

TEST_F(DrawPixelsTest, ClippedAtTheWindowEdgeAndByScissor) {
  std::vector<GLubyte> image(40 * 40 * 4, 200);
  glWindowPos2i(-5, -5);
  glDrawPixels(40, 40, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  EXPECT_EQ(count_pixels({200, 200, 200, 200}), width() * height());
  clear_to(0, 0, 0, 0);
  glEnable(GL_SCISSOR_TEST);
  glScissor(1, 2, 3, 4);
  glDrawPixels(40, 40, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  EXPECT_EQ(count_pixels({200, 200, 200, 200}), 12);
}

// RGBA bytes are drawn from the client's rows where they lie on a word boundary and converted
// a row at a time where they do not: from each address offset, with a row length and skipped
// pixels and rows, at zoom 1 and 2 (rows read twice), every pixel lands where it should.
TEST_F(DrawPixelsTest, RgbaBytesFromAnyAddressDrawTheirPixels) {
  const int w = 7, h = 5, row_length = 9, skip_pixels = 1, skip_rows = 2;
  auto byte_of = [](int x, int y, int c) { return GLubyte(x * 29 + y * 71 + c * 50 + 3); };
  glPixelStorei(GL_UNPACK_ROW_LENGTH, row_length);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, skip_pixels);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, skip_rows);
  for (int offset = 0; offset < 4; ++offset)
    for (int zoom_y = 1; zoom_y <= 2; ++zoom_y) {
      std::vector<GLubyte> storage(size_t(row_length) * (h + skip_rows) * 4 + 4, 0);
      GLubyte* const image = storage.data() + offset;
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          for (int c = 0; c < 4; ++c)
            image[((size_t(y) + skip_rows) * row_length + x + skip_pixels) * 4 + c] = byte_of(x, y, c);
      clear_to(0, 0, 0, 0);
      glPixelZoom(1.f, float(zoom_y));
      glWindowPos2i(2, 1);
      glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, image);
      ASSERT_EQ(error(), GLenum(GL_NO_ERROR));
      expect_image_at(2, 1, w, h, zoom_y, byte_of,
                      "offset " + std::to_string(offset) + " zoom " + std::to_string(zoom_y));
    }
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
}

// Images read as floats (GL_FLOAT, and bytes under pixel transfer) are read a row at a time too:
// every pixel of a multi-row image lands where it should, at zoom 1 and 2 (rows read twice),
// on the direct rows and on the per-fragment path (an alpha test that passes everything).
TEST_F(DrawPixelsTest, FloatRowsDrawTheirPixels) {
  const int w = 6, h = 5;
  auto byte_of = [](int x, int y, int c) { return GLubyte(x * 37 + y * 59 + c * 61 + 5); };
  std::vector<GLfloat> floats(size_t(w) * h * 4);
  std::vector<GLubyte> bytes(floats.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 4; ++c) {
        bytes[(size_t(y) * w + x) * 4 + c] = byte_of(x, y, c);
        floats[(size_t(y) * w + x) * 4 + c] = byte_of(x, y, c) / 255.f;
      }
  glAlphaFunc(GL_ALWAYS, 0.f);
  for (int source = 0; source < 2; ++source)
    for (int per_fragment = 0; per_fragment < 2; ++per_fragment)
      for (int zoom_y = 1; zoom_y <= 2; ++zoom_y) {
        clear_to(0, 0, 0, 0);
        if (per_fragment) glEnable(GL_ALPHA_TEST);
        // Bytes through an identity scale that still selects pixel transfer's float path.
        glPixelTransferf(GL_RED_BIAS, source == 1 ? 1e-9f : 0.f);
        glPixelZoom(1.f, float(zoom_y));
        glWindowPos2i(1, 2);
        if (source == 0) glDrawPixels(w, h, GL_RGBA, GL_FLOAT, floats.data());
        else glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
        glDisable(GL_ALPHA_TEST);
        glPixelTransferf(GL_RED_BIAS, 0.f);
        ASSERT_EQ(error(), GLenum(GL_NO_ERROR));
        expect_image_at(1, 2, w, h, zoom_y, byte_of,
                        "source " + std::to_string(source) + " per fragment " + std::to_string(per_fragment) +
                            " zoom " + std::to_string(zoom_y));
      }
}

// Byte images on a pipeline that changes nothing but for the depth test and an integer blend
// (blend8.h) are written straight into the colour buffer (PixelFragmentWriter::rgba8_row); an
// alpha test that passes everything sends the same image down the per-fragment path. Every
// format rgba8_rows.h reads, at several zooms, with and without a scissor rectangle, the depth
// test (over a depth buffer that is 0.1 on the left half, 0.5 on the right; the image at depth
// 0.25) and each integer blend (and one float blend), a region partly outside the window, gives
// the same colour and depth both ways.
TEST_F(DrawPixelsTest, BytesOnAPlainPipelineMatchTheFragmentPath) {
  const int w = 13, h = 11;
  std::vector<GLubyte> image(size_t(w) * h * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = GLubyte(i * 53 + (i >> 5) * 7);
  struct Format {
    GLenum format, type;
  };
  const Format formats[] = {{GL_RGBA, GL_UNSIGNED_BYTE},      {GL_BGRA, GL_UNSIGNED_BYTE},
                            {GL_RGB, GL_UNSIGNED_BYTE},       {GL_BGR, GL_UNSIGNED_BYTE},
                            {GL_LUMINANCE, GL_UNSIGNED_BYTE}, {GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE},
                            {GL_ALPHA, GL_UNSIGNED_BYTE},     {GL_RED, GL_UNSIGNED_BYTE},
                            {GL_GREEN, GL_UNSIGNED_BYTE},     {GL_BLUE, GL_UNSIGNED_BYTE},
                            {GL_RGBA, GL_UNSIGNED_INT_8_8_8_8}, {GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV}};
  const float zooms[][2] = {{1, 1}, {2, 3}, {-1, 1}, {0.5f, -2}};
  struct DepthTest {
    bool on;
    GLenum func;
    bool write;
  };
  const DepthTest depth_tests[] = {{false, GL_LESS, true}, {true, GL_LESS, true}, {true, GL_GREATER, true},
                                   {true, GL_LEQUAL, false}};
  struct Blend {
    bool on;
    GLenum src_rgb, dst_rgb, src_alpha, dst_alpha;
  };
  const Blend blends[] = {{false, GL_ONE, GL_ZERO, GL_ONE, GL_ZERO},
                          {true, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA},
                          {true, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE},
                          {true, GL_SRC_ALPHA, GL_ONE, GL_SRC_ALPHA, GL_ONE},
                          {true, GL_ONE, GL_ONE, GL_ONE, GL_ONE},
                          {true, GL_ONE_MINUS_DST_COLOR, GL_ZERO, GL_ONE, GL_ZERO}};  // float blending
  glAlphaFunc(GL_ALWAYS, 0.f);
  for (const Format& f : formats)
    for (const auto& zoom : zooms)
      for (const DepthTest& depth : depth_tests)
        for (const Blend& blend : blends)
        for (bool scissor : {false, true}) {
          if (blend.on && (zoom[0] != 1 || depth.func == GL_GREATER)) continue;  // enough cases
          if (blend.on) glEnable(GL_BLEND);
          glBlendFuncSeparate(blend.src_rgb, blend.dst_rgb, blend.src_alpha, blend.dst_alpha);
          std::vector<uint8_t> cleared, frames[2];
          std::vector<GLuint> depths[2];
          for (int pass = 0; pass < 2; ++pass) {
            clear_to(0.1f, 0.2f, 0.3f, 0.4f);
            clear_depth_halves(0.1, 0.5);
            cleared = read_all();
            if (pass == 1) glEnable(GL_ALPHA_TEST);
            if (scissor) glEnable(GL_SCISSOR_TEST);
            if (depth.on) glEnable(GL_DEPTH_TEST);
            glDepthFunc(depth.func);
            glDepthMask(depth.write ? GL_TRUE : GL_FALSE);
            glScissor(3, 2, 20, 9);
            glPixelZoom(zoom[0], zoom[1]);
            glWindowPos3f(zoom[0] < 0 ? 9.f : -2.f, zoom[1] < 0 ? 30.f : 4.f, 0.25f);
            glDrawPixels(w, h, f.format, f.type, image.data());
            glDisable(GL_ALPHA_TEST);
            glDisable(GL_SCISSOR_TEST);
            glDisable(GL_DEPTH_TEST);
            glDepthMask(GL_TRUE);
            ASSERT_EQ(error(), GLenum(GL_NO_ERROR));
            frames[pass] = read_all();
            depths[pass].resize(size_t(width()) * height());
            glReadPixels(0, 0, width(), height(), GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depths[pass].data());
          }
          glDisable(GL_BLEND);
          EXPECT_EQ(frames[0], frames[1]) << "format 0x" << std::hex << f.format << " type 0x" << f.type << std::dec
                                          << " zoom " << zoom[0] << "x" << zoom[1] << " scissor " << scissor
                                          << " depth test " << depth.on << " func 0x" << std::hex << depth.func
                                          << " blend 0x" << blend.src_rgb << " 0x" << blend.dst_rgb;
          EXPECT_EQ(depths[0], depths[1]);
          if (!depth.on) {
            EXPECT_NE(frames[0], cleared);  // something was drawn
          }
        }
}

// Images that are not bytes, or go through pixel transfer, reach the direct rows as floats,
// rounded as the fragment routines round them: out-of-range values, NaN, infinities and
// halfway values (k + 0.5) / 255 give the frame the per-fragment path gives.
TEST_F(DrawPixelsTest, FloatsOnAPlainPipelineMatchTheFragmentPath) {
  const int w = 16, h = 9;
  std::vector<GLfloat> image(size_t(w) * h * 4);
  const float specials[] = {-0.5f, 1.5f, std::nanf(""), INFINITY, -INFINITY, 0.5f / 255.f, 2.5f / 255.f, 1.f};
  for (size_t i = 0; i < image.size(); ++i)
    image[i] = i % 3 == 0 ? specials[(i / 3) % 8] : float((i * 37) % 300) / 255.f - 0.05f;
  glAlphaFunc(GL_ALWAYS, 0.f);
  for (const bool transfer : {false, true}) {
    std::vector<uint8_t> frames[2];
    for (int pass = 0; pass < 2; ++pass) {
      clear_to(0.1f, 0.2f, 0.3f, 0.4f);
      if (pass == 1) glEnable(GL_ALPHA_TEST);
      if (transfer) glPixelTransferf(GL_GREEN_SCALE, 0.5f);
      glWindowPos2i(3, 2);
      glDrawPixels(w, h, GL_RGBA, GL_FLOAT, image.data());
      glPixelTransferf(GL_GREEN_SCALE, 1.f);
      glDisable(GL_ALPHA_TEST);
      ASSERT_EQ(error(), GLenum(GL_NO_ERROR));
      frames[pass] = read_all();
    }
    EXPECT_EQ(frames[0], frames[1]) << "pixel transfer " << transfer;
  }
  // Pinned by hand: 1.5 and infinity clamp to 255, -0.5 and NaN to 0, 0.5 / 255 rounds to even 0.
  const GLfloat pixel_values[4] = {1.5f, std::nanf(""), 0.5f / 255.f, INFINITY};
  glWindowPos2i(0, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_FLOAT, pixel_values);
  EXPECT_EQ(pixel(0, 0), (Rgba{255, 0, 0, 255}));
}

// GL_DEPTH_COMPONENT images on a plain pipeline (PixelFragmentWriter::depth_row): the raster
// colour with each pixel's depth, through the depth test and an integer blend, give the colour
// and depth buffers the per-fragment path gives (an alpha test that passes everything).
TEST_F(DrawPixelsTest, DepthImagesOnAPlainPipelineMatchTheFragmentPath) {
  const int w = 13, h = 11;
  std::vector<GLuint> depths(size_t(w) * h);
  for (size_t i = 0; i < depths.size(); ++i) depths[i] = GLuint(i * 2654435761u);
  const float zooms[][2] = {{1, 1}, {2, 3}, {-1, 1}};
  glAlphaFunc(GL_ALWAYS, 0.f);
  glColor4f(0.9f, 0.6f, 0.3f, 0.7f);
  for (const auto& zoom : zooms)
    for (const GLenum func : {GL_LESS, GL_GREATER, GL_ALWAYS})
      for (const bool depth_write : {true, false})
        for (const bool blend : {false, true}) {
          std::vector<uint8_t> frames[2];
          std::vector<GLuint> stored[2];
          for (int pass = 0; pass < 2; ++pass) {
            clear_to(0.1f, 0.2f, 0.3f, 0.4f);
            clear_depth_halves(0.1, 0.5);
            if (pass == 1) glEnable(GL_ALPHA_TEST);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(func);
            glDepthMask(depth_write ? GL_TRUE : GL_FALSE);
            if (blend) glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glPixelZoom(zoom[0], zoom[1]);
            glWindowPos2i(zoom[0] < 0 ? 14 : 2, 3);
            glDrawPixels(w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depths.data());
            glDisable(GL_ALPHA_TEST);
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_BLEND);
            glDepthMask(GL_TRUE);
            ASSERT_EQ(error(), GLenum(GL_NO_ERROR));
            frames[pass] = read_all();
            stored[pass].resize(size_t(width()) * height());
            glReadPixels(0, 0, width(), height(), GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, stored[pass].data());
          }
          EXPECT_EQ(frames[0], frames[1]) << "zoom " << zoom[0] << " func 0x" << std::hex << func << std::dec
                                          << " depth write " << depth_write << " blend " << blend;
          EXPECT_EQ(stored[0], stored[1]);
        }
  glPixelZoom(1, 1);
  // Pinned: with GL_ALWAYS every pixel of the image takes the raster colour and its own depth.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glColor4f(1, 0, 1, 1);
  glWindowPos2i(0, 0);
  glDrawPixels(w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depths.data());
  glDisable(GL_DEPTH_TEST);
  EXPECT_EQ(count_pixels({255, 0, 255, 255}), w * h);
  EXPECT_EQ(depth_at(5, 4), depths[size_t(4) * w + 5] >> 8);
}

TEST_F(DrawPixelsTest, FragmentsGoThroughDepthAlphaBlendAndMasks) {
  glClearDepth(0.5);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const GLubyte red[4] = {255, 0, 0, 128};
  glWindowPos3f(0, 0, 0.75f);  // behind the cleared depth
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 0, 0}));
  glWindowPos3f(0, 0, 0.25f);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  EXPECT_EQ(pixel(0, 0), (Rgba{255, 0, 0, 128}));
  EXPECT_EQ(depth_at(0, 0), uint32_t(0.25 * 16777215 + 0.5));
  glDisable(GL_DEPTH_TEST);

  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.6f);
  glWindowPos2i(1, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  EXPECT_EQ(pixel(1, 0), (Rgba{0, 0, 0, 0}));
  glDisable(GL_ALPHA_TEST);

  clear_to(0, 0, 1, 1);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glWindowPos2i(2, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  EXPECT_TRUE(near_rgba(pixel(2, 0), {128, 0, 127, 192}, 1));
  glDisable(GL_BLEND);

  glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE);
  glWindowPos2i(3, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  EXPECT_EQ(pixel(3, 0), (Rgba{0, 0, 0, 128}));
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  glEnable(GL_COLOR_LOGIC_OP);
  glLogicOp(GL_XOR);
  glWindowPos2i(4, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  EXPECT_EQ(pixel(4, 0), (Rgba{255, 0, 255, 127}));
}

TEST_F(DrawPixelsTest, OrderedAfterQueuedTriangles) {
  glColor3f(0, 1, 0);
  glRectf(-1, -1, 1, 1);
  const GLubyte red[4] = {255, 0, 0, 255};
  glWindowPos2i(5, 5);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  glRectf(-1, -1, 0, 0);  // covers (5, 5) again, after the pixel
  EXPECT_EQ(pixel(5, 5), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(pixel(20, 20), (Rgba{0, 255, 0, 255}));
  glWindowPos2i(20, 20);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, red);
  EXPECT_EQ(pixel(20, 20), (Rgba{255, 0, 0, 255}));
}

TEST_F(DrawPixelsTest, DrawBufferNoneWritesNoColourButDepth) {
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDrawBuffer(GL_NONE);
  const GLubyte c[4] = {255, 255, 255, 255};
  glWindowPos3f(0, 0, 0.5f);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, c);
  const GLubyte bit = 0x80;
  glWindowPos3f(1, 0, 0.5f);
  glBitmap(1, 1, 0, 0, 0, 0, &bit);
  glDrawBuffer(GL_FRONT);
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(pixel(1, 0), (Rgba{0, 0, 0, 0}));
  EXPECT_EQ(depth_at(0, 0), uint32_t(0.5 * 16777215 + 0.5));
  EXPECT_EQ(depth_at(1, 0), uint32_t(0.5 * 16777215 + 0.5));
}

TEST_F(DrawPixelsTest, FogUsesTheRasterDistance) {
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, width(), 0, height(), -10, 10);
  glMatrixMode(GL_MODELVIEW);
  glRasterPos3f(0, 0, -5);  // 5 units from the eye
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 0.f);
  glFogf(GL_FOG_END, 10.f);
  const GLfloat blue[4] = {0, 0, 1, 1};
  glFogfv(GL_FOG_COLOR, blue);
  const GLubyte white[4] = {255, 255, 255, 255};
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, white);
  EXPECT_TRUE(near_rgba(pixel(0, 0), {128, 128, 255, 255}, 1));
}

TEST_F(DrawPixelsTest, DepthComponentWritesDepthWithTheRasterColour) {
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glColor4f(0, 1, 0, 1);
  glWindowPos2i(3, 3);
  const GLfloat depth[2] = {0.25f, 0.5f};
  glDrawPixels(2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  EXPECT_EQ(pixel(3, 3), (Rgba{0, 255, 0, 255}));
  EXPECT_EQ(depth_at(3, 3), uint32_t(0.25 * 16777215 + 0.5));
  EXPECT_EQ(depth_at(4, 3), uint32_t(0.5 * 16777215 + 0.5));
  glPixelTransferf(GL_DEPTH_SCALE, 2.f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.125f);
  glDrawPixels(2, 1, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
  EXPECT_EQ(depth_at(3, 3), 16777215u);  // read back through the same scale and bias
  glPixelTransferf(GL_DEPTH_SCALE, 1.f);
  glPixelTransferf(GL_DEPTH_BIAS, 0.f);
  EXPECT_EQ(depth_at(3, 3), uint32_t(0.625 * 16777215 + 0.5));
  EXPECT_EQ(depth_at(4, 3), 16777215u);  // clamped to 1
}

TEST_F(DrawPixelsTest, StencilIndexWritesUnderTheWriteMask) {
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  const GLubyte s[3] = {5, 0x7f, 0xff};
  glWindowPos2i(0, 0);
  glStencilMask(0x0f);
  glDrawPixels(3, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  EXPECT_EQ(stencil_at(0, 0), 5);
  EXPECT_EQ(stencil_at(1, 0), 0x0f);
  EXPECT_EQ(stencil_at(2, 0), 0x0f);
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 0, 0}));  // colour untouched
  glStencilMask(0xff);
  glPixelTransferi(GL_INDEX_OFFSET, 2);
  glPixelTransferi(GL_INDEX_SHIFT, 1);
  glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
  EXPECT_EQ(stencil_at(0, 0), 26);  // read back through the same shift and offset
  glPixelTransferi(GL_INDEX_OFFSET, 0);
  glPixelTransferi(GL_INDEX_SHIFT, 0);
  EXPECT_EQ(stencil_at(0, 0), 12);
  const GLuint map[2] = {200, 100};
  glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 2, map);
  glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
  glDrawPixels(2, 1, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);  // 5 & 1 = 1 -> 100, 0x7f & 1 -> 100
  glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
  EXPECT_EQ(stencil_at(0, 0), 100);
  const GLubyte bits = 0xa0;  // GL_BITMAP: 1, 0, 1, 0
  glDrawPixels(4, 1, GL_STENCIL_INDEX, GL_BITMAP, &bits);
  EXPECT_EQ(stencil_at(0, 0), 1);
  EXPECT_EQ(stencil_at(1, 0), 0);
  EXPECT_EQ(stencil_at(2, 0), 1);
}

TEST_F(DrawPixelsTest, ScaleBiasAndColourMaps) {
  glPixelTransferf(GL_RED_SCALE, 0.5f);
  glPixelTransferf(GL_GREEN_BIAS, 0.25f);
  glPixelTransferf(GL_ALPHA_SCALE, -1.f);
  const GLubyte c[4] = {255, 0, 255, 255};
  glWindowPos2i(0, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, c);
  glPixelTransferf(GL_RED_SCALE, 1.f);
  glPixelTransferf(GL_GREEN_BIAS, 0.f);
  glPixelTransferf(GL_ALPHA_SCALE, 1.f);
  EXPECT_EQ(pixel(0, 0), (Rgba{128, 64, 255, 0}));
  const GLfloat invert[2] = {1.f, 0.f};
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, invert);
  glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, invert);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  const GLubyte d[4] = {255, 255, 0, 255};
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, d);
  glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
  // R and B inverted; the G and A maps have one entry, 0.
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 255, 0}));
}

TEST_F(DrawPixelsTest, ColourIndicesGoThroughTheIndexMaps) {
  const GLfloat to_r[4] = {0.f, 1.f, 0.5f, 0.25f};
  const GLfloat one[1] = {1.f};
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 4, to_r);
  glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 1, one);
  const GLubyte idx[3] = {1, 2, 7};
  glWindowPos2i(0, 0);
  glDrawPixels(3, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);
  EXPECT_EQ(pixel(0, 0), (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(pixel(1, 0), (Rgba{128, 0, 0, 255}));
  EXPECT_EQ(pixel(2, 0), (Rgba{64, 0, 0, 255}));  // 7 & 3 = 3
}

TEST_F(DrawPixelsTest, InvalidRasterPositionDrawsNothing) {
  const GLubyte c[4] = {255, 255, 255, 255};
  glRasterPos2f(2.f, 0.f);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, c);
  EXPECT_EQ(error(), GLenum(GL_NO_ERROR));
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
}

TEST_F(DrawPixelsTest, Errors) {
  const GLubyte c[4] = {};
  glDrawPixels(-1, 1, GL_RGBA, GL_UNSIGNED_BYTE, c);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  glDrawPixels(1, 1, GL_RGBA8, GL_UNSIGNED_BYTE, c);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  glDrawPixels(1, 1, GL_RGBA, GL_RGBA, c);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  glDrawPixels(1, 1, GL_RGBA, GL_BITMAP, c);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  glDrawPixels(1, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE_3_3_2, c);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, c);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_8_8_8_8, c);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glBegin(GL_POINTS);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, c);
  glEnd();
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glPixelTransferi(GL_TEXTURE_2D, 1);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, reinterpret_cast<const GLfloat*>(c));
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, reinterpret_cast<const GLfloat*>(c));
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 257, nullptr);
  EXPECT_EQ(error(), GLenum(GL_INVALID_VALUE));
  glPixelMapfv(GL_TEXTURE_2D, 1, reinterpret_cast<const GLfloat*>(c));
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  GLfloat v[1];
  glGetPixelMapfv(GL_TEXTURE_2D, v);
  EXPECT_EQ(error(), GLenum(GL_INVALID_ENUM));
  EXPECT_EQ(count_pixels({0, 0, 0, 0}), width() * height());
}

class DrawPixelsNoDepthStencilTest : public DrawPixelsTest {
 protected:
  SurfaceSpec spec() const override {
    SurfaceSpec s;
    s.depth_bits = 0;
    s.stencil_bits = 0;
    return s;
  }
};

TEST_F(DrawPixelsNoDepthStencilTest, DepthAndStencilNeedTheirBuffers) {
  const GLfloat z[1] = {0.5f};
  glDrawPixels(1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, z);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glDrawPixels(1, 1, GL_STENCIL_INDEX, GL_FLOAT, z);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glCopyPixels(0, 0, 1, 1, GL_DEPTH);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
  glCopyPixels(0, 0, 1, 1, GL_STENCIL);
  EXPECT_EQ(error(), GLenum(GL_INVALID_OPERATION));
}

TEST_F(DrawPixelsTest, PixelMapsRoundTrip) {
  const GLushort values[4] = {0, 65535, 32768, 1};
  glPixelMapusv(GL_PIXEL_MAP_I_TO_G, 4, values);
  GLint size = 0;
  glGetIntegerv(GL_PIXEL_MAP_I_TO_G_SIZE, &size);
  EXPECT_EQ(size, 4);
  GLushort back[4] = {};
  glGetPixelMapusv(GL_PIXEL_MAP_I_TO_G, back);
  EXPECT_EQ(std::memcmp(back, values, sizeof values), 0);
  GLfloat f[4] = {};
  glGetPixelMapfv(GL_PIXEL_MAP_I_TO_G, f);
  EXPECT_EQ(f[1], 1.f);
  const GLuint indices[2] = {7, 9};
  glPixelMapuiv(GL_PIXEL_MAP_I_TO_I, 2, indices);
  GLuint ui[2] = {};
  glGetPixelMapuiv(GL_PIXEL_MAP_I_TO_I, ui);
  EXPECT_EQ(ui[0], 7u);
  EXPECT_EQ(ui[1], 9u);
  glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, &size);
  EXPECT_EQ(size, 1);
}

TEST_F(DrawPixelsTest, PixelModeSavedWithPixelModeBit) {
  glPixelTransferf(GL_RED_SCALE, 2.f);
  glPixelZoom(3.f, 4.f);
  glPushAttrib(GL_PIXEL_MODE_BIT);
  glPixelTransferf(GL_RED_SCALE, 5.f);
  glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
  glPixelZoom(1.f, 1.f);
  glPopAttrib();
  float v = 0;
  glGetFloatv(GL_RED_SCALE, &v);
  EXPECT_EQ(v, 2.f);
  glGetFloatv(GL_ZOOM_Y, &v);
  EXPECT_EQ(v, 4.f);
  GLboolean b = GL_TRUE;
  glGetBooleanv(GL_MAP_COLOR, &b);
  EXPECT_EQ(b, GL_FALSE);
}

TEST_F(DrawPixelsTest, CompiledListKeepsTheImageAndUnpackStateOfCompileTime) {
  GLubyte image[2][4] = {{1, 2, 3, 4}, {9, 9, 9, 9}};
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 1);
  glNewList(1, GL_COMPILE);
  glWindowPos2i(0, 0);
  glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, image);
  glEndList();
  EXPECT_EQ(pixel(0, 0), (Rgba{0, 0, 0, 0}));
  image[1][0] = 200;
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  glCallList(1);
  EXPECT_EQ(pixel(0, 0), (Rgba{9, 9, 9, 9}));
}

TEST_F(DrawPixelsTest, ReadPixelsAppliesPixelTransfer) {
  clear_to(0.2f, 0.4f, 0.6f, 0.8f);
  glPixelTransferf(GL_RED_SCALE, 2.f);
  glPixelTransferf(GL_BLUE_BIAS, 1.f);
  GLubyte p[4];
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, p);
  EXPECT_EQ(p[0], 102);
  EXPECT_EQ(p[1], 102);
  EXPECT_EQ(p[2], 255);
  EXPECT_EQ(p[3], 204);
}

}  // namespace
}  // namespace pineda::test
