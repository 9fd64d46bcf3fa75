// glReadPixels: every format and type, pack alignment, row length and skips, depth and
// stencil, and reads partly outside the surface.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

constexpr int kR = 51, kG = 102, kB = 153, kA = 204;  // 0.2, 0.4, 0.6, 0.8

class ReadPixelsTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    clear_to(kR / 255.f, kG / 255.f, kB / 255.f, kA / 255.f);
  }
};

// The expected value of one component byte value `k` (of 255) in `type`.
double expected_component(int k, GLenum type) {
  const double c = k / 255.0;
  switch (type) {
    case GL_UNSIGNED_BYTE: return k;
    case GL_BYTE: return std::round(c * 127);
    case GL_UNSIGNED_SHORT: return k * 257.0;
    case GL_SHORT: return std::round(c * 32767);
    case GL_UNSIGNED_INT: return k * 16843009.0;
    case GL_INT: return std::round(c * 2147483647.0);
    default: return c;  // GL_FLOAT
  }
}

double read_component(const uint8_t* p, GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: return *p;
    case GL_BYTE: return *reinterpret_cast<const int8_t*>(p);
    case GL_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p, 2); return v; }
    case GL_SHORT: { int16_t v; std::memcpy(&v, p, 2); return v; }
    case GL_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p, 4); return v; }
    case GL_INT: { int32_t v; std::memcpy(&v, p, 4); return v; }
    default: { float v; std::memcpy(&v, p, 4); return v; }
  }
}

int type_size(GLenum type) {
  switch (type) {
    case GL_UNSIGNED_BYTE: case GL_BYTE: return 1;
    case GL_UNSIGNED_SHORT: case GL_SHORT: return 2;
    default: return 4;
  }
}

struct FormatCase {
  GLenum format;
  std::vector<int> components;  // byte values expected, in order; -1: luminance (R+G+B clamped)
};

TEST_F(ReadPixelsTest, EveryFormatAndType) {
  const int lum = std::min(kR + kG + kB, 255);
  const FormatCase formats[] = {
      {GL_RGBA, {kR, kG, kB, kA}}, {GL_RGB, {kR, kG, kB}}, {GL_BGRA, {kB, kG, kR, kA}}, {GL_BGR, {kB, kG, kR}},
      {GL_RED, {kR}},              {GL_GREEN, {kG}},       {GL_BLUE, {kB}},            {GL_ALPHA, {kA}},
      {GL_LUMINANCE, {lum}},       {GL_LUMINANCE_ALPHA, {lum, kA}}};
  const GLenum types[] = {GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_SHORT,
                          GL_UNSIGNED_INT,  GL_INT,  GL_FLOAT};
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  for (const FormatCase& f : formats)
    for (GLenum type : types) {
      const int n = int(f.components.size()), size = type_size(type);
      std::vector<uint8_t> out(size_t(3 * 2 * n * size) + 16, 0xEE);
      glReadPixels(5, 7, 3, 2, f.format, type, out.data());
      ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR)) << std::hex << f.format << " " << type;
      for (int p = 0; p < 6; ++p)
        for (int c = 0; c < n; ++c) {
          const double got = read_component(&out[size_t((p * n + c) * size)], type);
          const double want = expected_component(f.components[c], type);
          const double tolerance = type == GL_FLOAT ? 1e-6 : 1;
          EXPECT_NEAR(got, want, tolerance) << std::hex << "format " << f.format << " type " << type << std::dec
                                            << " pixel " << p << " component " << c;
        }
      EXPECT_EQ(out[size_t(6 * n * size)], 0xEE) << "wrote past the image";
    }
}

TEST_F(ReadPixelsTest, PackAlignmentPadsRows) {
  for (GLint alignment : {1, 2, 4, 8}) {
    glPixelStorei(GL_PACK_ALIGNMENT, alignment);
    // 3 RGB bytes x 3 pixels = 9 bytes per row, padded to the alignment.
    const int stride = (9 + alignment - 1) / alignment * alignment;
    std::vector<uint8_t> out(size_t(stride) * 3, 0xEE);
    glReadPixels(0, 0, 3, 3, GL_RGB, GL_UNSIGNED_BYTE, out.data());
    for (int row = 0; row < 3; ++row) {
      for (int i = 0; i < 9; i += 3) {
        EXPECT_EQ(out[row * stride + i], kR) << alignment;
        EXPECT_EQ(out[row * stride + i + 2], kB) << alignment;
      }
      for (int pad = 9; row < 2 && pad < stride; ++pad) EXPECT_EQ(out[row * stride + pad], 0xEE) << alignment;
    }
  }
}

TEST_F(ReadPixelsTest, PackRowLengthAndSkips) {
  pixel_projection();
  glColor3ub(10, 20, 30);
  glRecti(2, 2, 3, 3);  // one distinct pixel at (2, 2)
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 10);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
  glPixelStorei(GL_PACK_SKIP_ROWS, 3);
  std::vector<uint8_t> out(10 * 8 * 4, 0xEE);
  glReadPixels(1, 1, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  auto at = [&](int col, int row) { return &out[size_t((row * 10 + col) * 4)]; };
  // Pixel (2, 2) of the surface is image pixel (1, 1): written at row 3 + 1, column 2 + 1.
  EXPECT_EQ(at(3, 4)[0], 10);
  EXPECT_EQ(at(3, 4)[1], 20);
  EXPECT_EQ(at(3, 4)[2], 30);
  EXPECT_EQ(at(2, 3)[0], kR);
  EXPECT_EQ(at(5, 6)[3], kA);
  EXPECT_EQ(at(1, 3)[0], 0xEE);  // skipped pixels untouched
  EXPECT_EQ(at(2, 2)[0], 0xEE);  // skipped rows untouched
  EXPECT_EQ(at(6, 3)[0], 0xEE);  // past the row's width
  EXPECT_EQ(at(2, 7)[0], 0xEE);  // past the last row
}

TEST_F(ReadPixelsTest, DepthComponentTypes) {
  glClearDepth(0.25);
  glClear(GL_DEPTH_BUFFER_BIT);
  GLuint u = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &u);
  EXPECT_NEAR(double(u), 0.25 * 4294967295.0, 512.0);
  GLushort s = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, &s);
  EXPECT_NEAR(double(s), 0.25 * 65535, 1.0);
  GLubyte b = 0;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_BYTE, &b);
  EXPECT_NEAR(double(b), 0.25 * 255, 1.0);
}

TEST_F(ReadPixelsTest, StencilIndexTypes) {
  glClearStencil(200);
  glClear(GL_STENCIL_BUFFER_BIT);
  GLuint u = 0;
  glReadPixels(3, 3, 1, 1, GL_STENCIL_INDEX, GL_UNSIGNED_INT, &u);
  EXPECT_EQ(u, 200u);
  GLfloat f = 0;
  glReadPixels(3, 3, 1, 1, GL_STENCIL_INDEX, GL_FLOAT, &f);
  EXPECT_EQ(f, 200.f);
  GLshort sh = 0;
  glReadPixels(3, 3, 1, 1, GL_STENCIL_INDEX, GL_SHORT, &sh);
  EXPECT_EQ(sh, 200);
}

TEST_F(ReadPixelsTest, ReadsOutsideTheSurfaceLeaveMemoryAndInsideIsRead) {
  std::vector<uint8_t> out(4 * 4 * 4, 0xEE);
  glReadPixels(width() - 2, height() - 2, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
  EXPECT_EQ(out[0], kR);                    // (w-2, h-2): inside
  EXPECT_EQ(out[(1 * 4 + 1) * 4 + 3], kA);  // (w-1, h-1): inside
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

TEST_F(ReadPixelsTest, Errors) {
  uint8_t out[64] = {};
  glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_VALUE));
  glReadPixels(0, 0, 1, 1, 0x1234, GL_UNSIGNED_BYTE, out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glReadPixels(0, 0, 1, 1, GL_RGBA, 0x1234, out);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
  glReadPixels(0, 0, 1, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, out);  // no colour-index buffers
  EXPECT_NE(glGetError(), GLenum(GL_NO_ERROR));
}

class ReadPixelsWithoutDepthTest : public GlTest {
 protected:
  SurfaceSpec spec() const override { return {8, 8, 0, 0}; }
};

TEST_F(ReadPixelsWithoutDepthTest, DepthAndStencilReadsAreInvalidOperation) {
  GLfloat f = 5;
  glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  glReadPixels(0, 0, 1, 1, GL_STENCIL_INDEX, GL_FLOAT, &f);
  EXPECT_EQ(glGetError(), GLenum(GL_INVALID_OPERATION));
  EXPECT_EQ(f, 5.f);
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

class DepthReadPrecisionTest : public GlTest, public ::testing::WithParamInterface<int> {
 protected:
  SurfaceSpec spec() const override { return {8, 8, GetParam(), 0}; }
};

// A stored depth value d of b bits reads as the unsigned integer d * (2^32 - 1) / (2^b - 1).
TEST_P(DepthReadPrecisionTest, UnsignedIntDepthIsExact) {
  const int bits = GetParam();
  const double max = bits == 32 ? 4294967295.0 : double((1ull << bits) - 1);
  glClearDepth(0.25);
  glClear(GL_DEPTH_BUFFER_BIT);
  const double stored = std::round(0.25 * max);
  GLuint u = 0;
  glReadPixels(1, 1, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, &u);
  EXPECT_NEAR(double(u), std::round(stored / max * 4294967295.0), 1.0);
}

INSTANTIATE_TEST_SUITE_P(Bits, DepthReadPrecisionTest, ::testing::Values(16, 24, 32));

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

TEST_F(ReadPixelsTest, PackSwapBytes) {
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
  GLushort rg[2] = {0, 0};
  glReadPixels(0, 0, 1, 1, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT, rg);
  const GLushort lum = GLushort(std::min(kR + kG + kB, 255) * 257), alpha = GLushort(kA * 257);
  EXPECT_EQ(rg[0], GLushort((lum >> 8) | (lum << 8)));
  EXPECT_EQ(rg[1], GLushort((alpha >> 8) | (alpha << 8)));
  GLuint red = 0;
  glReadPixels(0, 0, 1, 1, GL_RED, GL_UNSIGNED_INT, &red);
  EXPECT_EQ(red, __builtin_bswap32(GLuint(kR) * 16843009u));
  GLubyte bytes[4];
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, bytes);  // single bytes: unchanged
  EXPECT_EQ(bytes[0], kR);
  EXPECT_EQ(bytes[3], kA);
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// The byte formats read without conversion (state/pixels/color_byte_reads.h): every byte of
// the client image, from a surface of distinct pixels, under each pack layout, with a region
// partly outside the surface (its pixels there, row padding and skips left untouched).
TEST_F(ReadPixelsTest, ByteFormatsReadEveryPixelUnderEveryPackLayout) {
  const int w = width(), h = height();
  std::vector<uint8_t> drawn(size_t(w) * h * 4);
  for (size_t i = 0; i < drawn.size(); ++i) drawn[i] = uint8_t(i * 37 + (i >> 7) * 11);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  pixel_projection();
  glRasterPos2i(0, 0);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, drawn.data());
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  struct Format {
    GLenum format;
    int order[4];  // the drawn component each stored byte holds
    int n;
  };
  const Format formats[] = {{GL_RGBA, {0, 1, 2, 3}, 4}, {GL_BGRA, {2, 1, 0, 3}, 4}, {GL_RGB, {0, 1, 2, 0}, 3},
                            {GL_BGR, {2, 1, 0, 0}, 3}};
  const int x = -3, y = 5, rw = w + 2, rh = h - 9;  // rows y..y+rh-1, columns from -3 past the right edge
  for (const Format& f : formats)
    for (int alignment : {1, 4, 8})
      for (int row_length : {0, rw + 5})
        for (int skip : {0, 3}) {
          glPixelStorei(GL_PACK_ALIGNMENT, alignment);
          glPixelStorei(GL_PACK_ROW_LENGTH, row_length);
          glPixelStorei(GL_PACK_SKIP_PIXELS, skip);
          glPixelStorei(GL_PACK_SKIP_ROWS, skip);
          const int length = row_length ? row_length : rw;
          const size_t stride = (size_t(length) * f.n + alignment - 1) / alignment * alignment;
          const size_t offset = size_t(skip) * stride + size_t(skip) * f.n;
          std::vector<uint8_t> out(offset + stride * rh + 64, 0xEE);
          glReadPixels(x, y, rw, rh, f.format, GL_UNSIGNED_BYTE, out.data());
          ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
          std::vector<uint8_t> want(out.size(), 0xEE);
          for (int row = 0; row < rh; ++row)
            for (int col = 0; col < rw; ++col) {
              const int sx = x + col, sy = y + row;
              if (sx < 0 || sx >= w || sy < 0 || sy >= h) continue;
              for (int c = 0; c < f.n; ++c)
                want[offset + stride * row + size_t(col) * f.n + c] = drawn[(size_t(sy) * w + sx) * 4 + f.order[c]];
            }
          ASSERT_EQ(out, want) << std::hex << "format " << f.format << std::dec << " alignment " << alignment
                               << " row length " << row_length << " skip " << skip;
        }
}

}  // namespace
}  // namespace pineda::test

namespace pineda::test {
namespace {

// Depth and stencil read a row at a time (state/pixels/depth_stencil_reads.h) against the general
// path, which PACK_SWAP_BYTES selects (its bytes swapped back here): every depth type it takes
// at every depth size, under several pack layouts, a region partly outside the surface. Stencil
// bytes are compared with the indices drawn.
class DepthStencilRowsTest : public GlTest, public ::testing::WithParamInterface<int> {
 protected:
  SurfaceSpec spec() const override { return {19, 13, GetParam(), 8}; }
};

// glReadPixels into `size` bytes filled with 0xEE; `swap`: under PACK_SWAP_BYTES, each element
// of `element` bytes swapped back to the native order (the filler reads the same either way).
std::vector<uint8_t> read_rect(int x, int y, int w, int h, GLenum format, GLenum type, bool swap, size_t size,
                               size_t element) {
  std::vector<uint8_t> out(size, 0xEE);
  glPixelStorei(GL_PACK_SWAP_BYTES, swap ? GL_TRUE : GL_FALSE);
  glReadPixels(x, y, w, h, format, type, out.data());
  glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
  if (swap)
    for (size_t i = 0; i + element <= size; i += element) std::reverse(&out[i], &out[i + element]);
  return out;
}
// A w x h image of distinct RGBA bytes drawn over the surface from (0, 0); returned.
std::vector<uint8_t> draw_distinct_pixels(int w, int h) {
  std::vector<uint8_t> drawn(size_t(w) * h * 4);
  for (size_t i = 0; i < drawn.size(); ++i) drawn[i] = uint8_t(i * 37 + (i >> 7) * 11);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glWindowPos2i(0, 0);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, drawn.data());
  return drawn;
}

template <typename T>
std::vector<uint8_t> read_rect(int x, int y, int w, int h, GLenum format, GLenum type, bool swap, size_t size) {
  return read_rect(x, y, w, h, format, type, swap, size, sizeof(T));
}

TEST_P(DepthStencilRowsTest, DepthAndStencilRowsMatchTheGeneralPath) {
  const int w = width(), h = height();
  std::vector<GLuint> depths(size_t(w) * h);
  std::vector<GLubyte> indices(depths.size());
  for (size_t i = 0; i < depths.size(); ++i) {
    depths[i] = GLuint(i * 2654435761u);
    indices[i] = GLubyte(i * 7 + 3);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);
  glWindowPos2i(0, 0);
  glDrawPixels(w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depths.data());
  glDrawPixels(w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, indices.data());
  glDisable(GL_DEPTH_TEST);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  const int x = -2, y = 3, rw = w + 3, rh = h - 5;
  for (int alignment : {1, 8})
    for (int row_length : {0, rw + 3})
      for (int skip : {0, 2}) {
        glPixelStorei(GL_PACK_ALIGNMENT, alignment);
        glPixelStorei(GL_PACK_ROW_LENGTH, row_length);
        glPixelStorei(GL_PACK_SKIP_PIXELS, skip);
        glPixelStorei(GL_PACK_SKIP_ROWS, skip);
        const size_t size = size_t((row_length ? row_length : rw) + 8) * (rh + skip + 1) * 4;
        SCOPED_TRACE(::testing::Message() << "alignment " << alignment << " row length " << row_length << " skip " << skip);
        EXPECT_EQ(read_rect<GLuint>(x, y, rw, rh, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, false, size),
                  read_rect<GLuint>(x, y, rw, rh, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, true, size));
        EXPECT_EQ(read_rect<GLushort>(x, y, rw, rh, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, false, size),
                  read_rect<GLushort>(x, y, rw, rh, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, true, size));
        EXPECT_EQ(read_rect<GLfloat>(x, y, rw, rh, GL_DEPTH_COMPONENT, GL_FLOAT, false, size),
                  read_rect<GLfloat>(x, y, rw, rh, GL_DEPTH_COMPONENT, GL_FLOAT, true, size));
        const std::vector<uint8_t> stencil = read_rect<GLubyte>(x, y, rw, rh, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, false, size);
        std::vector<uint8_t> want(size, 0xEE);
        const int length = row_length ? row_length : rw;
        const size_t stride = (size_t(length) + alignment - 1) / alignment * alignment;
        for (int row = 0; row < rh; ++row)
          for (int col = 0; col < rw; ++col)
            if (x + col >= 0 && x + col < w && y + row < h)
              want[stride * (row + skip) + col + skip] = indices[size_t(y + row) * w + x + col];
        EXPECT_EQ(stencil, want);
        ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
      }
}

INSTANTIATE_TEST_SUITE_P(Bits, DepthStencilRowsTest, ::testing::Values(16, 24, 32));

// RGBA and BGRA as GL_UNSIGNED_INT_8_8_8_8(_REV) words (color_byte_reads.h) are the byte reads of
// the same format on a little-endian machine, each pixel's four bytes reversed for 8_8_8_8 and
// again under PACK_SWAP_BYTES; also from glGetTexImage.
TEST_F(ReadPixelsTest, PackedWordsAreTheBytesInWordOrder) {
  const int w = width(), h = height();
  const std::vector<uint8_t> drawn = draw_distinct_pixels(w, h);
  glBindTexture(GL_TEXTURE_2D, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, drawn.data());
  const size_t size = size_t(w) * h * 4;
  for (const GLenum format : {GL_RGBA, GL_BGRA})
    for (const GLenum type : {GL_UNSIGNED_INT_8_8_8_8, GL_UNSIGNED_INT_8_8_8_8_REV})
      for (const bool swap : {false, true})
        for (const bool texture : {false, true}) {
          auto read = [&](GLenum t, bool swapped) {
            std::vector<uint8_t> out(size, 0xEE);
            glPixelStorei(GL_PACK_SWAP_BYTES, swapped ? GL_TRUE : GL_FALSE);
            if (texture) glGetTexImage(GL_TEXTURE_2D, 0, format, t, out.data());
            else glReadPixels(0, 0, w, h, format, t, out.data());
            glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
            return out;
          };
          std::vector<uint8_t> want = read(GL_UNSIGNED_BYTE, false);
          if ((type == GL_UNSIGNED_INT_8_8_8_8) != swap)
            for (size_t i = 0; i < size; i += 4) std::reverse(&want[i], &want[i + 4]);
          EXPECT_EQ(read(type, swap), want) << std::hex << "format " << format << " type " << type << " swap " << swap
                                            << " texture " << texture;
        }
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// Colour read into unpacked types by table (state/pixels/color_component_reads.h) against the
// general path, which PACK_SWAP_BYTES selects: every format whose components are channels, every
// unpacked type, pack alignments, a region partly outside the surface. And GL_FLOAT pinned by
// hand: a stored byte k reads as k / 255.
TEST_F(ReadPixelsTest, ComponentTypesMatchTheGeneralPath) {
  const int w = width(), h = height();
  const std::vector<uint8_t> drawn = draw_distinct_pixels(w, h);
  const GLenum formats[] = {GL_RGBA, GL_BGRA,  GL_RGB,       GL_BGR,           GL_RED,
                            GL_GREEN, GL_BLUE, GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA};
  struct Type {
    GLenum type;
    size_t size;
  };
  const Type types[] = {{GL_UNSIGNED_BYTE, 1}, {GL_BYTE, 1}, {GL_UNSIGNED_SHORT, 2}, {GL_SHORT, 2},
                        {GL_UNSIGNED_INT, 4},  {GL_INT, 4},  {GL_FLOAT, 4}};
  const int x = -2, y = 3, rw = w + 3, rh = h - 5;
  const size_t size = size_t(rw + 8) * (rh + 1) * 16;
  for (const GLenum format : formats)
    for (const Type& t : types)
      for (int alignment : {1, 8}) {
        glPixelStorei(GL_PACK_ALIGNMENT, alignment);
        EXPECT_EQ(read_rect(x, y, rw, rh, format, t.type, false, size, t.size),
                  read_rect(x, y, rw, rh, format, t.type, true, size, t.size))
            << std::hex << "format " << format << " type " << t.type << std::dec << " alignment " << alignment;
      }
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  float rgba[4];
  glReadPixels(5, 6, 1, 1, GL_RGBA, GL_FLOAT, rgba);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(rgba[c], float(drawn[(size_t(6) * w + 5) * 4 + c] / 255.0)) << c;
  // Luminance is R + G + B, at most 1 (GL 2.1 4.3.2).
  GLubyte luminance[8];
  glReadPixels(0, 0, 8, 1, GL_LUMINANCE, GL_UNSIGNED_BYTE, luminance);
  int clamped = 0;
  for (int x = 0; x < 8; ++x) {
    const uint8_t* p = &drawn[size_t(x) * 4];
    const int sum = p[0] + p[1] + p[2];
    clamped += sum > 255;
    EXPECT_EQ(luminance[x], std::min(sum, 255)) << x;
  }
  EXPECT_GT(clamped, 0);
  EXPECT_LT(clamped, 8);
  ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

}  // namespace
}  // namespace pineda::test
