// UnitTextureAccess, the shaders' texture lookups: sample_2d_block (the short route of a block
// whose 16 lanes run) against sample() on the quads with a live pixel, whatever the other quads'
// coordinates; and samplers chosen with the draw (choose_fast_samplers, as DrawRecord holds them)
// against samplers the object chooses itself.
#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>

#include "raster/shader_textures.h"

namespace pineda::raster {
namespace {

using shader::kLanes;
using shader::LaneMask;

std::shared_ptr<const TextureImage> random_mipmapped(int size, std::mt19937& random) {
  auto image = std::make_shared<TextureImage>();
  for (int w = size;; w = std::max(w / 2, 1)) {
    TextureLevel level{w, w, CacheLineVector<uint32_t>(static_cast<size_t>(w) * w)};
    for (uint32_t& texel : level.texels.edit()) texel = static_cast<uint32_t>(random());
    image->levels.push_back(std::move(level));
    if (w == 1) break;
  }
  return image;
}

// Quads 0 and 1 magnified (a 64th of a texel per pixel), quads 2 and 3 minified (8 texels per
// pixel): a mipmapped texture reads level 0 for the first two and level 3 for the others.
// coords[0] and [1] are s and t; r and q stay zero.
void two_kinds_of_quads(float coords[4][kLanes]) {
  for (int q = 0; q < 4; ++q) {
    const float step = q < 2 ? 1.f / (64.f * 64.f) : 8.f / 64.f;
    for (int i = 0; i < 4; ++i) {
      coords[0][4 * q + i] = 0.3f + 0.1f * static_cast<float>(q) + step * static_cast<float>(i & 1);
      coords[1][4 * q + i] = 0.6f - 0.05f * static_cast<float>(q) + step * static_cast<float>(i >> 1);
    }
  }
}

// Unit u's fast samplers chosen for the draw, as DrawRecord::shader_samplers holds them.
std::array<FastSamplers, kMaxTextureImageUnits> chosen_for(const std::array<TextureUnit, kMaxTextureImageUnits>& units,
                                                          int u) {
  std::array<FastSamplers, kMaxTextureImageUnits> chosen{};
  chosen[static_cast<size_t>(u)] = choose_fast_samplers(*units[static_cast<size_t>(u)].image,
                                                        units[static_cast<size_t>(u)].sampler, SimdPath::Best);
  return chosen;
}

struct Lanes {
  alignas(64) float c[4][kLanes];
};

// sample_2d_block's lanes of the live quads equal sample()'s, bit for bit.
void expect_live_quads_equal(const Lanes& block, const Lanes& general, LaneMask live) {
  for (int q = 0; q < 4; ++q) {
    if (!((live >> (4 * q)) & 0xf)) continue;
    for (int c = 0; c < 4; ++c)
      for (int i = 4 * q; i < 4 * q + 4; ++i)
        EXPECT_EQ(std::memcmp(&block.c[c][i], &general.c[c][i], sizeof(float)), 0)
            << "lane " << i << " channel " << c << ": " << block.c[c][i] << " against " << general.c[c][i];
  }
}

TEST(ShaderTextures, BlockRouteChoosesTheLevelFromTheLiveQuadsAlone) {
  std::mt19937 random(7);
  std::array<TextureUnit, kMaxTextureImageUnits> units;
  units[2].image = random_mipmapped(64, random);
  units[2].sampler.min_filter = TexFilter::LinearMipmapNearest;
  alignas(64) float coords[4][kLanes] = {};
  two_kinds_of_quads(coords);
  const float *s = coords[0], *t = coords[1];
  const std::array<FastSamplers, kMaxTextureImageUnits> chosen = chosen_for(units, 2);
  ASSERT_NE(chosen[2].block, nullptr);
  EXPECT_EQ(chosen[2].level_zero_image, nullptr);  // mipmapped: the level depends on the quads
  for (const bool with_chosen : {false, true}) {
    const UnitTextureAccess textures(units, with_chosen ? &chosen : nullptr);
    for (const LaneMask live : {LaneMask{0x00FF}, LaneMask{0x0010}, LaneMask{0xFF00}, LaneMask{0x8000}}) {
      Lanes block, general;
      float* const out[4] = {block.c[0], block.c[1], block.c[2], block.c[3]};
      ASSERT_TRUE(textures.sample_2d_block(2, s, t, live, out)) << std::hex << live;
      textures.sample(2, shader::SamplerKind::Tex2D, coords, shader::LodMode::Implicit, nullptr, live, general.c);
      expect_live_quads_equal(block, general, live);
    }
    // Live quads at two levels: not the block route (sample() takes the lookup).
    Lanes block;
    float* const out[4] = {block.c[0], block.c[1], block.c[2], block.c[3]};
    EXPECT_FALSE(textures.sample_2d_block(2, s, t, 0xFFFF, out));
    EXPECT_FALSE(textures.sample_2d_block(2, s, t, 0x0101, out));
  }
}

TEST(ShaderTextures, LevelZeroRouteWritesEveryLaneAndMatchesSampleOnLiveQuads) {
  std::mt19937 random(8);
  std::array<TextureUnit, kMaxTextureImageUnits> units;
  units[0].image = random_mipmapped(64, random);
  units[0].sampler.min_filter = TexFilter::Linear;
  units[0].sampler.wrap_s = units[0].sampler.wrap_t = TexWrap::ClampToEdge;
  alignas(64) float coords[4][kLanes] = {};
  two_kinds_of_quads(coords);
  const float *s = coords[0], *t = coords[1];
  const std::array<FastSamplers, kMaxTextureImageUnits> chosen = chosen_for(units, 0);
  ASSERT_EQ(chosen[0].level_zero_image, units[0].image.get());
  for (const bool with_chosen : {false, true}) {
    const UnitTextureAccess textures(units, with_chosen ? &chosen : nullptr);
    for (const LaneMask live : {LaneMask{0xFFFF}, LaneMask{0x0F0F}, LaneMask{0x0001}}) {
      Lanes block, general;
      for (auto& channel : block.c)
        for (float& v : channel) v = -7.f;  // every lane is written
      float* const out[4] = {block.c[0], block.c[1], block.c[2], block.c[3]};
      ASSERT_TRUE(textures.sample_2d_block(0, s, t, live, out));
      for (auto& channel : block.c)
        for (float v : channel) EXPECT_NE(v, -7.f);
      textures.sample(0, shader::SamplerKind::Tex2D, coords, shader::LodMode::Implicit, nullptr, live, general.c);
      expect_live_quads_equal(block, general, live);
    }
  }
  // A unit without a texture has no short route.
  const UnitTextureAccess textures(units);
  Lanes block;
  float* const out[4] = {block.c[0], block.c[1], block.c[2], block.c[3]};
  EXPECT_FALSE(textures.sample_2d_block(1, s, t, 0xFFFF, out));
}

}  // namespace
}  // namespace pineda::raster
