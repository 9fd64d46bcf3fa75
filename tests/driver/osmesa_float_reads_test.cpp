// glReadPixels as GL_RGBA GL_FLOAT of RGBA words (state/pixels/color_component_reads.cpp, whose
// rows take a product instead of a division where the CPU has AVX2): from an OSMESA_RGBA buffer,
// rendered in place, and an OSMESA_RGB one, which has no alpha bits (Pineda renders into RGBA
// words and copies them out; the rows' AVX2 copy puts alpha 1 in every fourth lane). Every colour
// component reads as its byte over 255, bit for bit, in whole rows and in rows that end
// mid-vector; alpha as its byte over 255, or 1 without alpha bits.
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace {

class OSMesaFloatReads : public ::testing::TestWithParam<GLenum> {};

TEST_P(OSMesaFloatReads, EveryByteReadsAsItsQuotient) {
  constexpr int kWidth = 64, kHeight = 8;
  const bool opaque = GetParam() == OSMESA_RGB;
  OSMesaContext ctx = OSMesaCreateContextExt(GetParam(), 0, 0, 0, nullptr);
  ASSERT_NE(ctx, nullptr);
  std::vector<uint8_t> buffer(kWidth * kHeight * (opaque ? 3 : 4));
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight));
  // Rows 0-3: pixel i holds (i, 255 - i, 7i, 13i + 5) mod 256, so every channel takes all 256 values.
  std::vector<uint8_t> bytes(kWidth * 4 * 4);
  for (int i = 0; i < 256; ++i) {
    uint8_t* p = &bytes[size_t(i) * 4];
    p[0] = uint8_t(i);
    p[1] = uint8_t(255 - i);
    p[2] = uint8_t(7 * i);
    p[3] = uint8_t(13 * i + 5);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glWindowPos2i(0, 0);
  glDrawPixels(kWidth, 4, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
  // The whole rows, then 61 pixels from column 1 (rows that end 4 components past a multiple of 8).
  for (const int x0 : {0, 1}) {
    const int w = x0 == 0 ? kWidth : 61;
    std::vector<float> floats(size_t(w) * 4 * 4, -1.f);
    glReadPixels(x0, 0, w, 4, GL_RGBA, GL_FLOAT, floats.data());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    size_t wrong = 0;
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 4; ++c) {
          const uint8_t stored = bytes[(size_t(y) * kWidth + size_t(x0 + x)) * 4 + size_t(c)];
          const float expected = opaque && c == 3 ? 1.f : float(stored) / 255.f;
          const float got = floats[(size_t(y) * size_t(w) + size_t(x)) * 4 + size_t(c)];
          wrong += std::memcmp(&got, &expected, sizeof got) != 0;
        }
    EXPECT_EQ(wrong, 0u) << "from column " << x0;
  }
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

INSTANTIATE_TEST_SUITE_P(Formats, OSMesaFloatReads, ::testing::Values(GLenum(OSMESA_RGBA), GLenum(OSMESA_RGB)),
                         [](const ::testing::TestParamInfo<GLenum>& info) {
                           return info.param == OSMESA_RGB ? "RGB" : "RGBA";
                         });

}  // namespace
