// Hostile input: random garbage vertices, states and modes must never crash or touch memory
// outside the buffers (run under the sanitizer build to check the latter).
#include <gtest/gtest.h>

#include <cfloat>
#include <cstdlib>
#include <limits>
#include <memory>
#include <random>

#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

float garbage(std::mt19937& rng) {
  static const float specials[] = {0.f, -0.f, 1.f, -1.f, 1e-30f, -1e-30f, 1e30f, -1e30f, FLT_MAX, -FLT_MAX,
                                   FLT_MIN, std::numeric_limits<float>::infinity(),
                                   -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN(),
                                   std::numeric_limits<float>::denorm_min()};
  std::uniform_int_distribution<int> pick(0, 3);
  if (pick(rng) == 0) return specials[rng() % (sizeof specials / sizeof specials[0])];
  return std::uniform_real_distribution<float>(-3.f, 3.f)(rng);
}

// PINEDA_FUZZ_ROUNDS=N runs N framebuffers instead of 6, for longer runs by hand.
TEST(Robustness, RandomGarbageNeverCrashes) {
  std::mt19937 rng(2024);
  auto tex = std::make_shared<TextureImage>();
  tex->levels.push_back({3, 5, CacheLineVector<uint32_t>(15, 0x80ff40c0u)});
  tex->levels.push_back({1, 2, CacheLineVector<uint32_t>(2, 0xffffffffu)});
  for (int round = 0; round < (std::getenv("PINEDA_FUZZ_ROUNDS") ? std::atoi(std::getenv("PINEDA_FUZZ_ROUNDS")) : 6); ++round) {
    const int w = 1 + static_cast<int>(rng() % 150), h = 1 + static_cast<int>(rng() % 90);
    OwnedFramebuffer fb(w, h, round % 2 ? 16 : 32, round % 3 != 0, round % 2 ? ColorFormat::BGRA8 : ColorFormat::RGBA8);
    Renderer r(1 + round % 3);
    r.set_framebuffer(fb.fb);
    for (int d = 0; d < 60; ++d) {
      DrawState s;
      s.viewport = {static_cast<int>(rng() % 400) - 200, static_cast<int>(rng() % 400) - 200,
                    static_cast<int>(rng() % 20000), static_cast<int>(rng() % 20000), garbage(rng), garbage(rng)};
      s.scissor_test = rng() % 2;
      s.scissor = {static_cast<int>(rng() % 300) - 100, static_cast<int>(rng() % 300) - 100,
                   static_cast<int>(rng() % 2000) - 10, static_cast<int>(rng() % 2000) - 10};
      s.cull_face = rng() % 2;
      s.polygon_front = static_cast<PolygonMode>(rng() % 3);
      s.polygon_back = static_cast<PolygonMode>(rng() % 3);
      s.offset_fill = s.offset_line = s.offset_point = rng() % 2;
      s.offset_factor = garbage(rng);
      s.offset_units = garbage(rng);
      s.point_size = garbage(rng) * 50;
      s.line_width = garbage(rng) * 20;
      s.flat_shading = rng() % 2;
      s.alpha_test = rng() % 2;
      s.alpha_ref = garbage(rng);
      s.stencil_test = rng() % 2;
      s.stencil_front.ref = static_cast<int>(rng());
      s.stencil_front.depth_pass = static_cast<StencilOp>(rng() % 8);
      s.depth_test = rng() % 2;
      s.depth_func = static_cast<CompareFunc>(rng() % 8);
      s.blend = rng() % 2;
      s.blend_state.src_rgb = static_cast<BlendFactor>(rng() % 15);
      s.blend_state.dst_alpha = static_cast<BlendFactor>(rng() % 15);
      s.blend_state.eq_rgb = static_cast<BlendEquation>(rng() % 5);
      s.blend_state.color[0] = garbage(rng);
      s.logic_op_enabled = rng() % 4 == 0;
      s.logic_op = static_cast<LogicOp>(rng() % 16);
      s.color_write = {rng() % 2 == 0, true, rng() % 2 == 0, true};
      if (rng() % 2) {
        TextureUnit& u = s.texture_units[rng() % kMaxTextureUnits];
        u.image = tex;
        u.sampler.min_filter = static_cast<TexFilter>(rng() % 6);
        u.sampler.mag_filter = static_cast<TexFilter>(rng() % 2);
        u.sampler.wrap_s = static_cast<TexWrap>(rng() % 5);
        u.sampler.wrap_t = static_cast<TexWrap>(rng() % 5);
        u.sampler.min_lod = garbage(rng);
        u.sampler.max_lod = garbage(rng);
        u.env_mode = static_cast<TexEnvMode>(rng() % 5);
        u.env_color[1] = garbage(rng);
      }
      std::vector<ClipVertex> v(rng() % 12);
      for (ClipVertex& p : v) {
        for (float& c : p.clip) c = garbage(rng);
        if (rng() % 3) p.clip[3] = std::fabs(p.clip[3]);
        for (float& c : p.color) c = garbage(rng);
        for (float& c : p.back_color) c = garbage(rng);
        for (auto& tc : p.texcoord)
          for (float& c : tc) c = garbage(rng);
        p.edge_flag = rng() % 2;
      }
      std::vector<uint32_t> idx;
      if (rng() % 3 == 0)
        for (int i = 0; i < 10; ++i) idx.push_back(rng() % 16);
      r.draw(s, static_cast<Primitive>(rng() % 10), v, idx);
      if (rng() % 8 == 0) {
        ClearState c;
        c.color = c.depth = c.stencil = true;
        c.color_value[0] = garbage(rng);
        c.depth_value = garbage(rng);
        c.stencil_value = static_cast<int>(rng());
        c.scissor_test = rng() % 2;
        c.scissor = s.scissor;
        r.clear(c);
      }
    }
    r.flush();
  }
  SUCCEED();
}

}  // namespace
}  // namespace pineda::raster::test
