// Sampling parameters changed between draws (wrap modes, filters, LOD bias): each draw samples
// with the parameters set when it was issued, queued draws included, whether or not the
// change needs a new image (a minification filter that needs mipmaps makes a texture with one
// level incomplete; setting it back makes the texture complete again).
#include <vector>

#include "tests/e2e/support/gl_test.h"
#include "tests/e2e/support/window_quad.h"

// Its own namespace: a unity batch holds other files' colour names.
namespace pineda::test::sampling_draws {
namespace {

constexpr Rgba kRed{255, 0, 0, 255}, kBlue{0, 0, 255, 255}, kWhite{255, 255, 255, 255};

class SamplingParameterDrawsTest : public GlTest {
 protected:
  void SetUp() override {
    GlTest::SetUp();
    pixel_projection();
    clear_to(0, 0, 0, 0);
    glColor4f(1, 1, 1, 1);
    // A 2x1 texture: red left texel, blue right one, nearest filters.
    const uint8_t texels[8] = {255, 0, 0, 255, 0, 0, 255, 255};
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
  }
  void TearDown() override {
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GlTest::TearDown();
  }
  // s from 1.25 to 1.75 over [x, x + 4): REPEAT reads the left (red) texel, CLAMP_TO_EDGE the
  // right (blue) one.
  void draw_past_the_edge(float x) { draw_textured_rect(x, 0, x + 4, 4, 1.25f, 0, 1.75f, 1); }
};

TEST_F(SamplingParameterDrawsTest, EachQueuedDrawSamplesWithTheWrapModeSetBeforeIt) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  draw_past_the_edge(0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  draw_past_the_edge(8);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  draw_past_the_edge(16);
  EXPECT_EQ(pixel(1, 1), kRed);
  EXPECT_EQ(pixel(9, 1), kBlue);
  EXPECT_EQ(pixel(17, 1), kRed);
}

TEST_F(SamplingParameterDrawsTest, SettingTheSameValuesAgainChangesNothing) {
  for (int i = 0; i < 3; ++i) {
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.25f);
    draw_past_the_edge(8.f * float(i));
  }
  EXPECT_EQ(pixel(1, 1), kBlue);
  EXPECT_EQ(pixel(9, 1), kBlue);
  EXPECT_EQ(pixel(17, 1), kBlue);
}

TEST_F(SamplingParameterDrawsTest, AMipmapFilterOnOneLevelDisablesTheUnitUntilItIsSetBack) {
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  draw_past_the_edge(0);
  // Incomplete (GL 1.5 3.8.10): the unit is as if disabled, the quad takes the current colour.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  draw_past_the_edge(8);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  draw_past_the_edge(16);
  EXPECT_EQ(pixel(1, 1), kBlue);
  EXPECT_EQ(pixel(9, 1), kWhite);
  EXPECT_EQ(pixel(17, 1), kBlue);
}

TEST_F(SamplingParameterDrawsTest, MagnificationFilterChangesBetweenDrawsOfOneImage) {
  // s from 0.25 to 0.75 over 4 pixels: NEAREST gives red then blue, LINEAR a blend between.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  draw_textured_rect(0, 0, 4, 4, 0.25f, 0, 0.75f, 1);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  draw_textured_rect(8, 0, 12, 4, 0.25f, 0, 0.75f, 1);
  EXPECT_EQ(pixel(1, 1), kRed);
  EXPECT_EQ(pixel(2, 1), kBlue);
  // Pixel 9's centre is at s = 0.4375: u = 0.375, weights 0.625 of texel 0 (red) and 0.375 of
  // texel 1 (blue).
  const Rgba linear = pixel(9, 1);
  EXPECT_NEAR(linear[0], 159, 1);
  EXPECT_EQ(linear[1], 0);
  EXPECT_NEAR(linear[2], 96, 1);
}

}  // namespace
}  // namespace pineda::test::sampling_draws
