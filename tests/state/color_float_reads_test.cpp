// glReadPixels of an RGBA8 colour buffer as GL_RGBA GL_FLOAT (state/pixels/color_component_reads.h,
// whose rows take a product instead of a division where the CPU has AVX2): every stored byte k
// reads as k / 255 in float, bit for bit, in whole rows and in reads whose rows end mid-vector.
#include <cstring>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {
namespace {

class ColorFloatReadsTest : public GlTest {
 protected:
  SurfaceSpec spec() const override {
    SurfaceSpec s;
    s.width = 64;
    s.height = 8;
    return s;
  }
};

TEST_F(ColorFloatReadsTest, EveryStoredByteReadsAsItsQuotient) {
  // Rows 0-3: pixel i holds (i, 255 - i, 7i, 13i + 5) mod 256, so every channel takes all 256 values.
  std::vector<uint8_t> bytes(64 * 4 * 4);
  for (int i = 0; i < 256; ++i) {
    uint8_t* p = &bytes[size_t(i) * 4];
    p[0] = uint8_t(i);
    p[1] = uint8_t(255 - i);
    p[2] = uint8_t(7 * i);
    p[3] = uint8_t(13 * i + 5);
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glWindowPos2i(0, 0);
  glDrawPixels(64, 4, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
  std::vector<uint8_t> stored(bytes.size());
  glReadPixels(0, 0, 64, 4, GL_RGBA, GL_UNSIGNED_BYTE, stored.data());
  ASSERT_EQ(stored, bytes);
  // The whole rows, then 61 pixels from column 1 (each row ending 4 components past a multiple of 8).
  for (const int x0 : {0, 1}) {
    const int w = x0 == 0 ? 64 : 61;
    std::vector<float> floats(size_t(w) * 4 * 4, -1.f);
    glReadPixels(x0, 0, w, 4, GL_RGBA, GL_FLOAT, floats.data());
    ASSERT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    size_t wrong = 0;
    for (int y = 0; y < 4; ++y)
      for (int x = 0; x < w; ++x)
        for (int c = 0; c < 4; ++c) {
          const float expected = float(bytes[(size_t(y) * 64 + size_t(x0 + x)) * 4 + size_t(c)]) / 255.f;
          const float got = floats[(size_t(y) * size_t(w) + size_t(x)) * 4 + size_t(c)];
          wrong += std::memcmp(&got, &expected, sizeof got) != 0;
        }
    EXPECT_EQ(wrong, 0u) << "from column " << x0;
  }
}

}  // namespace
}  // namespace pineda::test
