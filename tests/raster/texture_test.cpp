// Texture filters, wrap modes, mipmap selection and the texture environment, exact values.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>

#include "raster/srgb.h"
#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

uint32_t rgba(int r, int g, int b, int a) {
  return static_cast<uint32_t>(r) | static_cast<uint32_t>(g) << 8 | static_cast<uint32_t>(b) << 16 |
         static_cast<uint32_t>(a) << 24;
}

// Renders a w x h framebuffer covered by one quad with texcoords (s0,t0)-(s1,t1).
struct Textured {
  Textured(int w, int h) : fb(w, h), w(w), h(h) { r.set_framebuffer(fb.fb); }
  void draw(const TextureUnit& unit, float s0, float s1, float t0 = 0.f, float t1 = 1.f,
            const float color[4] = nullptr) {
    DrawState s = state_for(w, h);
    s.texture_units[0] = unit;
    std::vector<ClipVertex> v{vertex(-1, -1), vertex(1, -1), vertex(1, 1), vertex(-1, 1)};
    const float st[4][2] = {{s0, t0}, {s1, t0}, {s1, t1}, {s0, t1}};
    for (int i = 0; i < 4; ++i) {
      v[i].texcoord[0][0] = st[i][0];
      v[i].texcoord[0][1] = st[i][1];
      if (color)
        for (int c = 0; c < 4; ++c) v[i].color[c] = color[c];
    }
    r.draw(s, Primitive::Quads, v);
    r.flush();
  }
  const uint8_t* px(int x, int y) const { return fb.pixel(x, y); }
  OwnedFramebuffer fb;
  Renderer r{1};
  int w, h;
};

TextureUnit unit_with(std::shared_ptr<TextureImage> image, TexFilter min, TexFilter mag, TexWrap wrap) {
  TextureUnit u;
  u.image = std::move(image);
  u.sampler.min_filter = min;
  u.sampler.mag_filter = mag;
  u.sampler.wrap_s = u.sampler.wrap_t = wrap;
  u.env_mode = TexEnvMode::Replace;
  return u;
}

std::shared_ptr<TextureImage> checker2x2() {
  auto t = std::make_shared<TextureImage>();
  // Row 0 (t = 0) first: red, green; row 1: blue, white.
  t->levels.push_back({2, 2, {rgba(255, 0, 0, 255), rgba(0, 255, 0, 255), rgba(0, 0, 255, 255), rgba(255, 255, 255, 255)}});
  return t;
}

TEST(Texture, NearestMagnificationPicksTexels) {
  Textured q(4, 4);
  q.draw(unit_with(checker2x2(), TexFilter::Nearest, TexFilter::Nearest, TexWrap::Repeat), 0, 1);
  const uint8_t expect[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) {
      const int texel = (y / 2) * 2 + x / 2;
      for (int c = 0; c < 3; ++c) EXPECT_EQ(q.px(x, y)[c], expect[texel][c]) << x << "," << y;
    }
}

std::shared_ptr<TextureImage> black_white_row() {
  auto t = std::make_shared<TextureImage>();
  t->levels.push_back({2, 1, {rgba(0, 0, 0, 255), rgba(255, 255, 255, 255)}});
  return t;
}

// Red of the 4 pixels across s in [0, 1]: centres at s = 1/8, 3/8, 5/8, 7/8, u = 2s - 1/2.
std::array<int, 4> linear_row(TexWrap wrap, const float border[4] = nullptr) {
  Textured q(4, 1);
  TextureUnit u = unit_with(black_white_row(), TexFilter::Linear, TexFilter::Linear, wrap);
  if (border)
    for (int c = 0; c < 4; ++c) u.sampler.border_color[c] = border[c];
  q.draw(u, 0, 1);
  return {q.px(0, 0)[0], q.px(1, 0)[0], q.px(2, 0)[0], q.px(3, 0)[0]};
}

TEST(Texture, LinearFilterWithEachWrapMode) {
  EXPECT_EQ(linear_row(TexWrap::ClampToEdge), (std::array<int, 4>{0, 64, 191, 255}));
  EXPECT_EQ(linear_row(TexWrap::MirroredRepeat), (std::array<int, 4>{0, 64, 191, 255}));
  EXPECT_EQ(linear_row(TexWrap::Repeat), (std::array<int, 4>{64, 64, 191, 191}));
  const float grey_border[4] = {0.4f, 0.4f, 0.4f, 1.f};
  // CLAMP and CLAMP_TO_BORDER blend with the border at the ends (0.25 * 0.4 = 0.1 -> 26;
  // 0.75 * 1 + 0.25 * 0.4 = 0.85 -> 217).
  EXPECT_EQ(linear_row(TexWrap::Clamp, grey_border), (std::array<int, 4>{26, 64, 191, 217}));
  EXPECT_EQ(linear_row(TexWrap::ClampToBorder, grey_border), (std::array<int, 4>{26, 64, 191, 217}));
}

TEST(Texture, NearestWrapModesOutsideZeroOne) {
  // s from -1 to 1 over 8 pixels: centres at s = -7/8 ... 7/8 on a 2-texel row.
  auto run = [](TexWrap wrap) {
    Textured q(8, 1);
    TextureUnit u = unit_with(black_white_row(), TexFilter::Nearest, TexFilter::Nearest, wrap);
    u.sampler.border_color[0] = 0.4f;
    q.draw(u, -1, 1);
    std::array<int, 8> out{};
    for (int x = 0; x < 8; ++x) out[x] = q.px(x, 0)[0];
    return out;
  };
  EXPECT_EQ(run(TexWrap::Repeat), (std::array<int, 8>{0, 0, 255, 255, 0, 0, 255, 255}));
  EXPECT_EQ(run(TexWrap::MirroredRepeat), (std::array<int, 8>{255, 255, 0, 0, 0, 0, 255, 255}));
  EXPECT_EQ(run(TexWrap::ClampToEdge), (std::array<int, 8>{0, 0, 0, 0, 0, 0, 255, 255}));
  EXPECT_EQ(run(TexWrap::ClampToBorder), (std::array<int, 8>{102, 102, 102, 102, 0, 0, 255, 255}));
}

std::shared_ptr<TextureImage> mip_chain() {
  auto t = std::make_shared<TextureImage>();
  t->levels.push_back({4, 4, CacheLineVector<uint32_t>(16, rgba(255, 0, 0, 255))});
  t->levels.push_back({2, 2, CacheLineVector<uint32_t>(4, rgba(0, 255, 0, 255))});
  t->levels.push_back({1, 1, CacheLineVector<uint32_t>(1, rgba(0, 0, 255, 255))});
  return t;
}

TEST(Texture, MipmapLevelSelection) {
  // 2x2 pixels showing a 4x4 texture: 2 texels per pixel, lambda = 1.
  auto level_colour = [](TexFilter min, float min_lod = -1000.f, float max_lod = 1000.f) {
    Textured q(2, 2);
    TextureUnit u = unit_with(mip_chain(), min, TexFilter::Nearest, TexWrap::Repeat);
    u.sampler.min_lod = min_lod;
    u.sampler.max_lod = max_lod;
    q.draw(u, 0, 1);
    return std::array<int, 3>{q.px(0, 0)[0], q.px(0, 0)[1], q.px(0, 0)[2]};
  };
  EXPECT_EQ(level_colour(TexFilter::NearestMipmapNearest), (std::array<int, 3>{0, 255, 0}));
  EXPECT_EQ(level_colour(TexFilter::LinearMipmapLinear), (std::array<int, 3>{0, 255, 0}));
  EXPECT_EQ(level_colour(TexFilter::Nearest), (std::array<int, 3>{255, 0, 0}));
  EXPECT_EQ(level_colour(TexFilter::NearestMipmapNearest, -1000.f, 0.f), (std::array<int, 3>{255, 0, 0}));
  EXPECT_EQ(level_colour(TexFilter::NearestMipmapNearest, 2.f), (std::array<int, 3>{0, 0, 255}));
  // lambda 1.5 between levels 1 and 2: half green, half blue.
  EXPECT_EQ(level_colour(TexFilter::NearestMipmapLinear, 1.5f), (std::array<int, 3>{0, 128, 128}));
}

TEST(Texture, EnvironmentModesAndBaseFormats) {
  struct Case {
    TexEnvMode mode;
    TexBaseFormat format;
    uint32_t texel;
    std::array<int, 4> expect;
  };
  // Fragment colour (0.4, 0.6, 0.8, 0.5); env colour (1, 0, 0.2, 0.6). The texels are stored
  // as texture_format.cpp stores them (L in R, G and B, I in all four): REPLACE and MODULATE of
  // these formats read them channel by channel (DrawRecord::texture_in_lanes).
  const Case cases[] = {
      {TexEnvMode::Replace, TexBaseFormat::RGBA, rgba(255, 0, 51, 102), {255, 0, 51, 102}},
      {TexEnvMode::Replace, TexBaseFormat::RGB, rgba(255, 0, 51, 102), {255, 0, 51, 128}},
      {TexEnvMode::Replace, TexBaseFormat::Alpha, rgba(255, 0, 51, 102), {102, 153, 204, 102}},
      {TexEnvMode::Replace, TexBaseFormat::Luminance, rgba(51, 51, 51, 255), {51, 51, 51, 128}},
      {TexEnvMode::Replace, TexBaseFormat::Intensity, rgba(51, 51, 51, 51), {51, 51, 51, 51}},
      {TexEnvMode::Modulate, TexBaseFormat::RGBA, rgba(255, 128, 0, 51), {102, 77, 0, 26}},
      {TexEnvMode::Modulate, TexBaseFormat::LuminanceAlpha, rgba(128, 128, 128, 255), {51, 77, 102, 128}},
      {TexEnvMode::Decal, TexBaseFormat::RGBA, rgba(255, 255, 255, 51), {133, 173, 214, 128}},
      {TexEnvMode::Decal, TexBaseFormat::RGB, rgba(255, 255, 255, 51), {255, 255, 255, 128}},
      {TexEnvMode::Blend, TexBaseFormat::RGB, rgba(255, 0, 128, 0), {255, 153, 127, 128}},
      {TexEnvMode::Blend, TexBaseFormat::Intensity, rgba(128, 128, 128, 128), {179, 76, 127, 140}},
      {TexEnvMode::Add, TexBaseFormat::RGBA, rgba(51, 255, 0, 128), {153, 255, 204, 64}},
      {TexEnvMode::Add, TexBaseFormat::Intensity, rgba(51, 51, 51, 51), {153, 204, 255, 179}},
  };
  const float frag[4] = {0.4f, 0.6f, 0.8f, 0.5f};
  for (const Case& c : cases) {
    auto t = std::make_shared<TextureImage>();
    t->base_format = c.format;
    t->levels.push_back({1, 1, {c.texel}});
    TextureUnit u = unit_with(t, TexFilter::Nearest, TexFilter::Nearest, TexWrap::Repeat);
    u.env_mode = c.mode;
    const float env[4] = {1.f, 0.f, 0.2f, 0.6f};
    for (int i = 0; i < 4; ++i) u.env_color[i] = env[i];
    Textured q(2, 2);
    q.draw(u, 0, 1, 0, 1, frag);
    for (int ch = 0; ch < 4; ++ch)
      EXPECT_EQ(q.px(1, 1)[ch], c.expect[ch]) << static_cast<int>(c.mode) << " " << static_cast<int>(c.format) << " " << ch;
  }
}

TEST(Texture, UnitsChainInOrderAndSkipDisabledOnes) {
  auto red = std::make_shared<TextureImage>();
  red->levels.push_back({1, 1, {rgba(255, 0, 0, 255)}});
  auto grey = std::make_shared<TextureImage>();
  grey->levels.push_back({1, 1, {rgba(128, 128, 128, 128)}});
  DrawState s = state_for(2, 2);
  s.texture_units[0] = unit_with(red, TexFilter::Nearest, TexFilter::Nearest, TexWrap::Repeat);  // Replace
  s.texture_units[2] = unit_with(grey, TexFilter::Nearest, TexFilter::Nearest, TexWrap::Repeat);
  s.texture_units[2].env_mode = TexEnvMode::Modulate;
  OwnedFramebuffer fb(2, 2);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  r.draw(s, Primitive::Quads, std::vector<ClipVertex>{vertex(-1, -1), vertex(1, -1), vertex(1, 1), vertex(-1, 1)});
  r.flush();
  EXPECT_EQ(fb.pixel(0, 0)[0], 128);
  EXPECT_EQ(fb.pixel(0, 0)[1], 0);
  EXPECT_EQ(fb.pixel(0, 0)[3], 128);
}

TEST(Texture, ProjectiveCoordinatesDivideByQ) {
  // (s, q) = (0.75 q, q) with q varying: s/q = 0.75 everywhere, the second texel of a 2x1 row.
  Textured q(4, 4);
  TextureUnit u = unit_with(black_white_row(), TexFilter::Nearest, TexFilter::Nearest, TexWrap::Repeat);
  DrawState s = state_for(4, 4);
  s.texture_units[0] = u;
  std::vector<ClipVertex> v{vertex(-1, -1), vertex(1, -1), vertex(1, 1), vertex(-1, 1)};
  const float qs[4] = {1.f, 3.f, 0.5f, 2.f};
  for (int i = 0; i < 4; ++i) {
    v[i].texcoord[0][0] = 0.75f * qs[i];
    v[i].texcoord[0][1] = 0.25f * qs[i];
    v[i].texcoord[0][3] = qs[i];
  }
  q.r.draw(s, Primitive::Quads, v);
  q.r.flush();
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) EXPECT_EQ(q.px(x, y)[0], 255) << x << "," << y;
}

TEST(Texture, IncompleteImagesDisableTheUnit) {
  auto t = std::make_shared<TextureImage>();
  t->levels.push_back({4, 4, CacheLineVector<uint32_t>(3, 0)});  // too few texels
  Textured q(2, 2);
  TextureUnit u = unit_with(t, TexFilter::Nearest, TexFilter::Nearest, TexWrap::Repeat);
  q.draw(u, 0, 1);
  EXPECT_EQ(q.px(0, 0)[0], 255);  // untextured white
}

}  // namespace
}  // namespace pineda::raster::test

namespace pineda::raster {
namespace {

// GL 2.1 equation 3.27 at a few exact points.
TEST(SrgbDecode, FollowsTheSpecCurve) {
  const auto& decode = srgb_decode_table();
  EXPECT_EQ(decode[0], 0.f);
  EXPECT_EQ(decode[255], 1.f);
  EXPECT_NEAR(decode[0x80], 0.2158605, 1e-6);
  EXPECT_NEAR(decode[10], 10 / 255.0 / 12.92, 1e-7);  // the linear segment (10 / 255 <= 0.04045)
  EXPECT_NEAR(decode[11], std::pow((11 / 255.0 + 0.055) / 1.055, 2.4), 1e-7);
  TextureLevel level;
  level.srgb = true;
  const F4 rgba = texel_to_rgba(level, 0x80FF0080u);  // R 0x80, G 0, B 0xFF, A 0x80
  EXPECT_NEAR(rgba[0], 0.2158605f, 1e-6f);
  EXPECT_EQ(rgba[1], 0.f);
  EXPECT_EQ(rgba[2], 1.f);
  EXPECT_EQ(rgba[3], 128 / 255.f);  // alpha is linear
}

}  // namespace
}  // namespace pineda::raster
