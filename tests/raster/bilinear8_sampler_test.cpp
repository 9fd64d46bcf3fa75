// The RGBA8 lane sampler: which samplers it takes, 8-bit weights, exact texels at their
// centres, and the mipmap blend.
#include <gtest/gtest.h>

#include <memory>

#include "raster/sampler_bilinear8.h"

namespace pineda::raster {
namespace {

TextureImage one_level(int w, int h, std::vector<uint32_t> texels) {
  TextureImage image;
  image.levels.push_back({w, h, std::move(texels)});
  return image;
}

Sampler linear(TexWrap wrap, TexFilter min = TexFilter::Linear) {
  Sampler s;
  s.min_filter = min;
  s.mag_filter = TexFilter::Linear;
  s.wrap_s = s.wrap_t = wrap;
  return s;
}

TEST(Bilinear8Sampler, TakesOnlyLinearPlanarColourImagesWithRepeatOrClampToEdge) {
  const TextureImage image = one_level(1, 1, {0});
  EXPECT_NE(select_bilinear8_sampler(image, linear(TexWrap::Repeat)), nullptr);
  EXPECT_NE(select_bilinear8_sampler(image, linear(TexWrap::ClampToEdge, TexFilter::LinearMipmapLinear)), nullptr);
  EXPECT_NE(select_bilinear8_sampler(image, linear(TexWrap::Repeat, TexFilter::LinearMipmapNearest)), nullptr);
  EXPECT_EQ(select_bilinear8_sampler(image, linear(TexWrap::MirroredRepeat)), nullptr);
  EXPECT_EQ(select_bilinear8_sampler(image, linear(TexWrap::ClampToBorder)), nullptr);
  EXPECT_EQ(select_bilinear8_sampler(image, linear(TexWrap::Clamp)), nullptr);
  EXPECT_EQ(select_bilinear8_sampler(image, linear(TexWrap::Repeat, TexFilter::NearestMipmapLinear)), nullptr);
  Sampler nearest_mag = linear(TexWrap::Repeat);
  nearest_mag.mag_filter = TexFilter::Nearest;
  EXPECT_EQ(select_bilinear8_sampler(image, nearest_mag), nullptr);
  TextureImage depth = image;
  depth.depth = true;
  EXPECT_EQ(select_bilinear8_sampler(depth, linear(TexWrap::Repeat)), nullptr);
  TextureImage cube = image;
  cube.kind = TexKind::Cube;
  EXPECT_EQ(select_bilinear8_sampler(cube, linear(TexWrap::Repeat)), nullptr);
}

TEST(Bilinear8Sampler, TexelCentresGiveTheTexelExactly) {
  const TextureImage image = one_level(2, 2, {0x04030201u, 0x80ff7f00u, 0x10203040u, 0xfffefdfcu});
  const Sampler sampler = linear(TexWrap::Repeat);
  F4 out[4];
  // Pixels at the four texel centres; the quad spans one texel per pixel (lambda 0).
  select_bilinear8_sampler(image, sampler)(image, sampler, F4{0.25f, 0.75f, 0.25f, 0.75f},
                                           F4{0.25f, 0.25f, 0.75f, 0.75f}, out);
  const uint32_t texels[4] = {0x04030201u, 0x80ff7f00u, 0x10203040u, 0xfffefdfcu};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 4; ++c)
      EXPECT_EQ(out[c][i], static_cast<float>((texels[i] >> (8 * c)) & 0xff) * (1.f / 255.f)) << i << " " << c;
}

TEST(Bilinear8Sampler, WeightsTruncateToOne256th) {
  // Texels 0 and 255 along s; u = 2s - 0.5 = 0.3 weighs the second by floor(0.3 * 256) / 256.
  const TextureImage image = one_level(2, 1, {0u, 0xffffffffu});
  const Sampler sampler = linear(TexWrap::ClampToEdge);
  F4 out[4];
  const float s = 0.4f;
  select_bilinear8_sampler(image, sampler)(image, sampler, F4{s, s, s, s}, F4{0.5f, 0.5f, 0.5f, 0.5f}, out);
  for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(out[c][0], 76.f / 256.f);
}

TEST(Bilinear8Sampler, MipmapBlendUsesLambdaInOne256th) {
  TextureImage image = one_level(2, 2, {0u, 0u, 0u, 0u});
  image.levels.push_back({1, 1, {0xffffffffu}});
  const Sampler sampler = linear(TexWrap::Repeat, TexFilter::LinearMipmapLinear);
  F4 out[4];
  // One texel per half pixel along x and y: rho^2 = 2, lambda = 0.5.
  select_bilinear8_sampler(image, sampler)(image, sampler, F4{0.f, 0.5f, 0.f, 0.5f}, F4{0.f, 0.5f, 0.f, 0.5f}, out);
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(out[c][i], 0.5f) << i << " " << c;
}

}  // namespace
}  // namespace pineda::raster
