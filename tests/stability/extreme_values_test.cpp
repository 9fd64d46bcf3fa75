// Extreme values that are not coordinates far away: w scaled to 1e-30 or 1e30, denormal
// components, NaN and infinity in colours and texture coordinates. Exact outcomes.
#include <cfloat>
#include <cmath>
#include <limits>
#include <string>

#include "tests/stability/case_table.h"
#include "tests/stability/exact_coverage.h"

namespace pineda::test {
namespace {

using ExtremeValues = ExactCoverageTest;

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A triangle given in homogeneous coordinates scaled by s covers exactly what the unscaled
// one covers: (x, y, z, w) and (sx, sy, sz, sw) are the same point.
TEST_F(ExtremeValues, HomogeneousScaleOfTinyAndHugeWIsTheSameTriangle) {
  const SubPoint a{3 * kSub + 11, 2 * kSub + 128}, b{120 * kSub + 128, 20 * kSub + 5}, c{50 * kSub + 77, 61 * kSub + 128};
  std::vector<uint8_t> expected = zero_counts();
  add_exact(expected, a, b, c);
  for (float s : {1.0f, 1e-30f, 1e-20f, 1e20f, 1e30f, 1e38f}) {
    begin_exact_counting();
    glBegin(GL_TRIANGLES);
    for (const SubPoint& p : {a, b, c}) {
      const double x = double(p.x) / (kSub * width() / 2) - 1.0, y = double(p.y) / (kSub * height() / 2) - 1.0;
      glVertex4f(float(x) * s, float(y) * s, 0.f, s);
    }
    glEnd();
    expect_case("vertices scaled by w = " + case_text(s) + ": pixels off the exact coverage", 0,
                mismatches(expected, hits()));
  }
}

// Denormal coordinates are tiny numbers, not garbage: a vertex at (1e-40, -1e-40, 1e-41)
// in NDC is the window centre, to within far less than a sub-pixel.
TEST_F(ExtremeValues, DenormalComponentsAreTinyNumbers) {
  const SubPoint centre{64 * kSub, 32 * kSub}, b{127 * kSub, 1 * kSub + 100}, c{90 * kSub + 13, 63 * kSub};
  std::vector<uint8_t> expected = zero_counts();
  add_exact(expected, centre, b, c);
  const float denormals[] = {1e-40f, -1e-40f, FLT_MIN / 4, -FLT_TRUE_MIN};
  for (float d : denormals) {
    ASSERT_EQ(std::fpclassify(d), FP_SUBNORMAL);
    begin_exact_counting();
    glBegin(GL_TRIANGLES);
    glVertex4f(d, -d, d, 1.f + d);
    vertex(b), vertex(c);
    glEnd();
    expect_case("denormal " + case_text(d) + " in x, y, z, w: pixels off the exact coverage", 0,
                mismatches(expected, hits()));
  }
}

// Colour channels that are NaN or infinite: NaN becomes 0, +inf 1 and -inf 0 (Pineda's
// defined outcome, as llvmpipe's clamps give), the other channels are untouched.
TEST_F(ExtremeValues, NanAndInfiniteColourChannelsClamp) {
  struct Case {
    float value;
    int byte;
  };
  for (const Case& k : {Case{kNan, 0}, Case{kInf, 255}, Case{-kInf, 0}})
    for (int channel = 0; channel < 4; ++channel) {
      glDisable(GL_STENCIL_TEST);
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
      pixel_projection();
      clear_to(0, 0, 0, 0);
      float color[4] = {0.2f, 0.6f, 1.0f, 0.4f};
      color[channel] = k.value;
      glColor4fv(color);
      glRectf(10, 10, 20, 20);  // smooth shading: all four vertices share the colour
      Rgba expected = {to_byte(0.2), to_byte(0.6), to_byte(1.0), to_byte(0.4)};
      expected[channel] = k.byte;
      const Rgba got = pixel(15, 15);
      const std::string name = "colour channel " + std::to_string(channel) + " = " + case_text(k.value);
      expect_case(name + ": pixel (15,15)", case_text(expected[0]) + "," + case_text(expected[1]) + "," +
                                                case_text(expected[2]) + "," + case_text(expected[3]),
                  case_text(got[0]) + "," + case_text(got[1]) + "," + case_text(got[2]) + "," + case_text(got[3]));
      expect_case(name + ": GL error", GLenum(GL_NO_ERROR), glGetError());
    }
}

// NaN or infinite texture coordinates on a one-colour texture: every fragment still gets
// that colour (a texel of the texture, never garbage), with every filter.
TEST_F(ExtremeValues, NanAndInfiniteTexCoordsSampleTheTexture) {
  const uint8_t texel[4] = {40, 120, 200, 255};
  std::vector<uint8_t> image;
  for (int i = 0; i < 4 * 4; ++i) image.insert(image.end(), texel, texel + 4);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glTexImage2D(GL_TEXTURE_2D, 2, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glEnable(GL_TEXTURE_2D);
  pixel_projection();
  for (GLenum filter : {GL_NEAREST, GL_LINEAR, GL_LINEAR_MIPMAP_LINEAR})
    for (float bad : {kNan, kInf, -kInf}) {
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter == GL_NEAREST ? GL_NEAREST : GL_LINEAR);
      clear_to(0, 0, 0, 0);
      glBegin(GL_QUADS);
      glTexCoord2f(bad, 0), glVertex2f(0, 0);
      glTexCoord2f(1, bad), glVertex2f(32, 0);
      glTexCoord2f(bad, bad), glVertex2f(32, 32);
      glTexCoord2f(0, 1), glVertex2f(0, 32);
      glEnd();
      expect_case("tex coord " + case_text(bad) + ", filter 0x" + [&] {
                    char b[8];
                    std::snprintf(b, sizeof b, "%x", filter);
                    return std::string(b);
                  }() + ": pixels not the texel colour",
                  0, 32 * 32 - count_pixels({40, 120, 200, 255}));
    }
  glDeleteTextures(1, &tex);
}

}  // namespace
}  // namespace pineda::test
