// OSMesa: contexts rendering into the caller's memory, in each format and layout.
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <thread>
#include <vector>

namespace {

using Bytes = std::vector<uint8_t>;

// Clears to (r, g, b, a) in 0..255 units exactly representable as floats / 255.
void clear(int r, int g, int b, int a) {
  glClearColor(r / 255.0f, g / 255.0f, b / 255.0f, a / 255.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

Bytes repeat(const Bytes& pixel, size_t count) {
  Bytes out;
  for (size_t i = 0; i < count; ++i) out.insert(out.end(), pixel.begin(), pixel.end());
  return out;
}

struct FormatCase {
  GLenum format;
  Bytes pixel;  // the bytes of a clear to (10, 20, 30, 40)
};

// A context of the case's format current on a 7x5 buffer with one spare pixel past its end,
// which must stay untouched.
class OSMesaFormat : public ::testing::TestWithParam<FormatCase> {
 protected:
  static constexpr int w = 7, h = 5;
  void SetUp() override {
    ctx = OSMesaCreateContextExt(GetParam().format, 0, 0, 0, nullptr);
    ASSERT_NE(ctx, nullptr);
    buffer.assign(w * h * bpp() + bpp(), 0xEE);
    ASSERT_TRUE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, w, h));
  }
  void TearDown() override {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    if (ctx) OSMesaDestroyContext(ctx);
  }
  size_t bpp() const { return GetParam().pixel.size(); }
  // The buffer with every pixel the case's (10, 20, 30, 40).
  Bytes filled() const {
    Bytes expected = repeat(GetParam().pixel, w * h);
    expected.insert(expected.end(), bpp(), 0xEE);
    return expected;
  }

  OSMesaContext ctx = nullptr;
  Bytes buffer;
};

TEST_P(OSMesaFormat, ClearFillsTheBufferExactly) {
  const FormatCase& c = GetParam();
  EXPECT_EQ(OSMesaGetCurrentContext(), ctx);
  clear(10, 20, 30, 40);
  glFinish();
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
  EXPECT_EQ(buffer, filled());

  GLint value = 0;
  OSMesaGetIntegerv(OSMESA_WIDTH, &value);
  EXPECT_EQ(value, w);
  OSMesaGetIntegerv(OSMESA_HEIGHT, &value);
  EXPECT_EQ(value, h);
  OSMesaGetIntegerv(OSMESA_FORMAT, &value);
  EXPECT_EQ(value, static_cast<GLint>(c.format));
  OSMesaGetIntegerv(OSMESA_TYPE, &value);
  EXPECT_EQ(value, GL_UNSIGNED_BYTE);
  OSMesaGetIntegerv(OSMESA_Y_UP, &value);
  EXPECT_EQ(value, 1);
  OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &value);
  EXPECT_EQ(value, 0);

  GLint cw = 0, ch = 0, cf = 0;
  void* cb = nullptr;
  EXPECT_TRUE(OSMesaGetColorBuffer(ctx, &cw, &ch, &cf, &cb));
  EXPECT_EQ(cw, w);
  EXPECT_EQ(ch, h);
  EXPECT_EQ(cf, static_cast<GLint>(c.format));
  EXPECT_EQ(cb, buffer.data());

  EXPECT_TRUE(OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0));
  EXPECT_EQ(OSMesaGetCurrentContext(), nullptr);
}

// glDrawPixels of RGBA bytes with nothing in the pipeline to change them writes them straight
// into the buffer (PixelFragmentWriter::rgba8_row): in each format's own byte order.
TEST_P(OSMesaFormat, DrawPixelsStoresBytesInTheBufferOrder) {
  const Bytes image = repeat({10, 20, 30, 40}, w * h);
  glWindowPos2i(0, 0);
  glDrawPixels(w, h, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glFinish();
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
  EXPECT_EQ(buffer, filled());
}

// glReadPixels as floats (color_component_reads.h) in each buffer order; a buffer without alpha
// (RGB, BGR) reads alpha 1.
TEST_P(OSMesaFormat, ReadPixelsAsFloats) {
  clear(10, 20, 30, 40);
  float rgba[4] = {};
  glReadPixels(2, 3, 1, 1, GL_RGBA, GL_FLOAT, rgba);
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
  const float alpha = bpp() == 3 ? 1.f : float(40 / 255.0);
  EXPECT_EQ(rgba[0], float(10 / 255.0));
  EXPECT_EQ(rgba[1], float(20 / 255.0));
  EXPECT_EQ(rgba[2], float(30 / 255.0));
  EXPECT_EQ(rgba[3], alpha);
}

// glCopyPixels of colour (copied rows of stored words, PixelRectImage::rgba8) leaves the copy's
// bytes those of its source in every buffer order.
TEST_P(OSMesaFormat, CopyPixelsCopiesTheStoredBytes) {
  Bytes image(3 * h * 4);
  for (size_t i = 0; i < image.size(); ++i) image[i] = uint8_t(i * 37 + 11);
  glWindowPos2i(0, 0);
  glDrawPixels(3, h, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glWindowPos2i(4, 0);
  glCopyPixels(0, 0, 3, h, GL_COLOR);
  glFinish();
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
  for (int y = 0; y < h; ++y) {
    const uint8_t* row = buffer.data() + size_t(y) * w * bpp();
    EXPECT_EQ(Bytes(row + 4 * bpp(), row + 7 * bpp()), Bytes(row, row + 3 * bpp())) << "row " << y;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Formats, OSMesaFormat,
    ::testing::Values(FormatCase{OSMESA_RGBA, {10, 20, 30, 40}},
                      FormatCase{OSMESA_BGRA, {30, 20, 10, 40}},
                      FormatCase{OSMESA_ARGB, {40, 10, 20, 30}},
                      FormatCase{OSMESA_RGB, {10, 20, 30}},
                      FormatCase{OSMESA_BGR, {30, 20, 10}}),
    [](const auto& info) {
      switch (info.param.format) {
        case OSMESA_RGBA: return "RGBA";
        case OSMESA_BGRA: return "BGRA";
        case OSMESA_ARGB: return "ARGB";
        case OSMESA_RGB: return "RGB";
        default: return "BGR";
      }
    });

// Clears the bottom row only (scissor), so that the row order in memory shows.
void clear_bottom_row(int width) {
  clear(0, 0, 0, 0);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, width, 1);
  clear(255, 255, 255, 255);
  glDisable(GL_SCISSOR_TEST);
  glFinish();
}

class OSMesaLayout : public ::testing::TestWithParam<GLenum> {};

TEST_P(OSMesaLayout, YUpPutsTheBottomRowFirst) {
  const GLenum format = GetParam();
  const int bpp = format == OSMESA_RGB ? 3 : 4;
  OSMesaContext ctx = OSMesaCreateContextExt(format, 0, 0, 0, nullptr);
  const int w = 4, h = 3;
  Bytes buffer(w * h * bpp, 0x55);
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, w, h));
  clear_bottom_row(w);
  Bytes white(w * bpp, 255), black(w * bpp * (h - 1), 0);
  Bytes expected = white;
  expected.insert(expected.end(), black.begin(), black.end());
  EXPECT_EQ(buffer, expected);

  // Top-down: the bottom row is the last one in memory.
  OSMesaPixelStore(OSMESA_Y_UP, 0);
  GLint value = 1;
  OSMesaGetIntegerv(OSMESA_Y_UP, &value);
  EXPECT_EQ(value, 0);
  clear_bottom_row(w);
  expected = black;
  expected.insert(expected.end(), white.begin(), white.end());
  EXPECT_EQ(buffer, expected);
  EXPECT_EQ(glGetError(), GL_NO_ERROR);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

TEST_P(OSMesaLayout, RowLengthLeavesPaddingAlone) {
  const GLenum format = GetParam();
  const int bpp = format == OSMESA_RGB ? 3 : 4;
  OSMesaContext ctx = OSMesaCreateContextExt(format, 0, 0, 0, nullptr);
  const int w = 3, h = 2, row = 5;
  Bytes buffer(row * h * bpp, 0x55);
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, w, h));
  OSMesaPixelStore(OSMESA_ROW_LENGTH, row);
  GLint value = 0;
  OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &value);
  EXPECT_EQ(value, row);
  clear(255, 255, 255, 255);
  glFinish();
  Bytes expected;
  for (int y = 0; y < h; ++y) {
    expected.insert(expected.end(), w * bpp, 255);
    expected.insert(expected.end(), (row - w) * bpp, 0x55);
  }
  EXPECT_EQ(buffer, expected);
  OSMesaPixelStore(OSMESA_ROW_LENGTH, -1);
  EXPECT_EQ(glGetError(), GL_INVALID_VALUE);
  OSMesaPixelStore(0x7777, 1);
  EXPECT_EQ(glGetError(), GL_INVALID_ENUM);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

INSTANTIATE_TEST_SUITE_P(InPlaceAndConverted, OSMesaLayout,
                         ::testing::Values(GLenum(OSMESA_RGBA), GLenum(OSMESA_RGB)),
                         [](const auto& info) { return info.param == OSMESA_RGBA ? "RGBA" : "RGB"; });

TEST(OSMesa, ConvertedFormatKeepsUserContentUntilDrawnOver) {
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGB, 0, 0, 0, nullptr);
  Bytes buffer = {1, 2, 3, 4, 5, 6};
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 2, 1));
  glFinish();
  EXPECT_EQ(buffer, (Bytes{1, 2, 3, 4, 5, 6}));
  uint8_t rgba[4] = {};
  glReadPixels(1, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
  EXPECT_EQ(Bytes(rgba, rgba + 4), (Bytes{4, 5, 6, 255}));
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

TEST(OSMesa, BadInputFails) {
  EXPECT_EQ(OSMesaCreateContext(OSMESA_COLOR_INDEX, nullptr), nullptr);
  EXPECT_EQ(OSMesaCreateContext(OSMESA_RGB_565, nullptr), nullptr);
  EXPECT_EQ(OSMesaCreateContext(0x7777, nullptr), nullptr);
  OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, nullptr);
  ASSERT_NE(ctx, nullptr);
  Bytes buffer(16 * 16 * 4, 0);
  EXPECT_FALSE(OSMesaMakeCurrent(ctx, nullptr, GL_UNSIGNED_BYTE, 16, 16));
  EXPECT_FALSE(OSMesaMakeCurrent(nullptr, buffer.data(), GL_UNSIGNED_BYTE, 16, 16));
  EXPECT_FALSE(OSMesaMakeCurrent(ctx, buffer.data(), GL_FLOAT, 16, 16));
  EXPECT_FALSE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_SHORT, 16, 16));
  EXPECT_FALSE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 0, 16));
  EXPECT_FALSE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 16, -1));
  EXPECT_FALSE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 100000, 1));
  EXPECT_EQ(OSMesaGetCurrentContext(), nullptr);
  // A context not yet bound has no buffers.
  GLint w = -1, h = -1, f = -1;
  void* p = &w;
  EXPECT_FALSE(OSMesaGetColorBuffer(ctx, &w, &h, &f, &p));
  EXPECT_EQ(p, nullptr);
  EXPECT_EQ(w, 0);
  EXPECT_FALSE(OSMesaGetDepthBuffer(ctx, &w, &h, &f, &p));
  EXPECT_FALSE(OSMesaGetColorBuffer(nullptr, &w, &h, &f, &p));
  OSMesaDestroyContext(ctx);
  OSMesaDestroyContext(nullptr);
}

TEST(OSMesa, CreateContextAttribs) {
  const int ok[] = {OSMESA_FORMAT, OSMESA_BGRA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 8,
                    OSMESA_CONTEXT_MAJOR_VERSION, 1, OSMESA_CONTEXT_MINOR_VERSION, 1, 0};
  OSMesaContext ctx = OSMesaCreateContextAttribs(ok, nullptr);
  ASSERT_NE(ctx, nullptr);
  Bytes buffer(8 * 8 * 4);
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 8, 8));
  GLint depth_bits = 0, stencil_bits = 0;
  glGetIntegerv(GL_DEPTH_BITS, &depth_bits);
  glGetIntegerv(GL_STENCIL_BITS, &stencil_bits);
  EXPECT_EQ(depth_bits, 24);
  EXPECT_EQ(stencil_bits, 8);
  GLint w = 0, h = 0, bytes = 0;
  void* depth = nullptr;
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  ASSERT_TRUE(OSMesaGetDepthBuffer(ctx, &w, &h, &bytes, &depth));
  EXPECT_EQ(w, 8);
  EXPECT_EQ(h, 8);
  EXPECT_EQ(bytes, 4);
  EXPECT_EQ(static_cast<uint32_t*>(depth)[0], 0xFFFFFFu);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);

  const int too_new[] = {OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  EXPECT_EQ(OSMesaCreateContextAttribs(too_new, nullptr), nullptr);
  const int core[] = {OSMESA_PROFILE, OSMESA_CORE_PROFILE, 0};
  EXPECT_EQ(OSMesaCreateContextAttribs(core, nullptr), nullptr);
  const int unknown[] = {0x7777, 1, 0};
  EXPECT_EQ(OSMesaCreateContextAttribs(unknown, nullptr), nullptr);
}

TEST(OSMesa, MaxSizeAndProcAddress) {
  GLint value = 0;
  OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &value);
  EXPECT_EQ(value, 16384);
  OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &value);
  EXPECT_EQ(value, 16384);
  EXPECT_EQ(OSMesaGetProcAddress("glClear"), reinterpret_cast<OSMESAproc>(&glClear));
  EXPECT_EQ(OSMesaGetProcAddress("OSMesaMakeCurrent"),
            reinterpret_cast<OSMESAproc>(&OSMesaMakeCurrent));
  EXPECT_EQ(OSMesaGetProcAddress("glNoSuchFunction"), nullptr);
  EXPECT_EQ(OSMesaGetProcAddress(nullptr), nullptr);
}

TEST(OSMesa, ContextCurrentOnAnotherThreadCannotBeBound) {
  OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, nullptr);
  Bytes a(4 * 4 * 4), b(4 * 4 * 4);
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, a.data(), GL_UNSIGNED_BYTE, 4, 4));
  GLboolean other = GL_TRUE;
  std::thread([&] { other = OSMesaMakeCurrent(ctx, b.data(), GL_UNSIGNED_BYTE, 4, 4); }).join();
  EXPECT_FALSE(other);
  OSMesaDestroyContext(ctx);
  EXPECT_EQ(OSMesaGetCurrentContext(), nullptr);
}

TEST(OSMesa, TwoThreadsRenderIndependently) {
  auto worker = [](GLenum format, int r, int g, int b, Bytes pixel, bool* ok) {
    OSMesaContext ctx = OSMesaCreateContext(format, nullptr);
    const int w = 33, h = 17;
    Bytes buffer(w * h * pixel.size(), 0);
    *ok = ctx && OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, w, h);
    for (int frame = 0; frame < 20 && *ok; ++frame) {
      clear(r, g, b, 255);
      glFinish();
      *ok = buffer == repeat(pixel, w * h);
    }
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx);
  };
  bool ok_a = false, ok_b = false;
  std::thread a(worker, GLenum(OSMESA_RGBA), 255, 0, 0, Bytes{255, 0, 0, 255}, &ok_a);
  std::thread b(worker, GLenum(OSMESA_BGR), 0, 0, 255, Bytes{255, 0, 0}, &ok_b);
  a.join();
  b.join();
  EXPECT_TRUE(ok_a);
  EXPECT_TRUE(ok_b);
}

}  // namespace

namespace {

TEST(OSMesa, ThreadEndingWithAContextCurrentReleasesIt) {
  OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGB, nullptr);
  Bytes a(2 * 2 * 3, 0), b(2 * 2 * 3, 0);
  std::thread([&] {
    ASSERT_TRUE(OSMesaMakeCurrent(ctx, a.data(), GL_UNSIGNED_BYTE, 2, 2));
    clear(1, 2, 3, 255);
  }).join();
  // The binding ended with the thread: the image got what was drawn.
  EXPECT_EQ(a, repeat({1, 2, 3}, 4));
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, b.data(), GL_UNSIGNED_BYTE, 2, 2));
  OSMesaDestroyContext(ctx);
}

}  // namespace
