// glReadPixels as GL_RGBA GL_FLOAT from an OSMESA_RGB context, whose buffer has no alpha bits
// (Pineda renders into RGBA words and copies them out): whole rows of the stored words go
// through the float rows of state/pixels/color_component_reads.cpp, whose AVX2 copy puts alpha 1
// in every fourth lane. Every colour component is its byte over 255, bit for bit; alpha is 1.
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

namespace {

TEST(OSMesaFloatReads, AnRgbBufferReadsItsBytesOver255AndAlphaOne) {
  constexpr int kWidth = 64, kHeight = 8;
  OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGB, 0, 0, 0, nullptr);
  ASSERT_NE(ctx, nullptr);
  std::vector<uint8_t> buffer(kWidth * kHeight * 3);
  ASSERT_TRUE(OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight));
  // Rows 0-3: pixel i holds (i, 255 - i, 7i) mod 256 (every channel all 256 values) and an alpha
  // byte that the buffer does not keep.
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
  // 61 pixels from column 1: rows that end 4 components past a multiple of 8.
  constexpr int kRead = 61;
  std::vector<float> floats(size_t(kRead) * 4 * 4, -1.f);
  glReadPixels(1, 0, kRead, 4, GL_RGBA, GL_FLOAT, floats.data());
  EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
  size_t wrong = 0;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < kRead; ++x)
      for (int c = 0; c < 4; ++c) {
        const float expected = c == 3 ? 1.f : float(bytes[(size_t(y) * kWidth + size_t(1 + x)) * 4 + size_t(c)]) / 255.f;
        const float got = floats[(size_t(y) * kRead + size_t(x)) * 4 + size_t(c)];
        wrong += std::memcmp(&got, &expected, sizeof got) != 0;
      }
  EXPECT_EQ(wrong, 0u);
  OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(ctx);
}

}  // namespace
