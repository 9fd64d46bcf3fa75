// Occlusion counting: a draw with a SampleCounter adds the samples that pass depth and
// stencil; the sum is the same for any thread count.
#include <gtest/gtest.h>

#include <memory>

#include "raster/draw_record.h"
#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

std::vector<ClipVertex> full_quad(float z) {
  return {vertex(-1, -1, z), vertex(1, -1, z), vertex(1, 1, z), vertex(-1, 1, z)};
}

TEST(SampleCounter, CountsCoveredPixelsWithoutTests) {
  OwnedFramebuffer fb(100, 70);
  Renderer r(2);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  DrawState s = state_for(100, 70);
  s.sample_counter = std::make_shared<SampleCounter>();
  r.draw(s, Primitive::Quads, full_quad(0.f));
  r.flush();
  EXPECT_EQ(s.sample_counter->passed.load(), 100u * 70u);
}

TEST(SampleCounter, DepthAndStencilFailuresAreNotCounted) {
  OwnedFramebuffer fb(64, 64);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  DrawState s = state_for(64, 64);
  s.depth_test = true;
  s.viewport = {0, 0, 32, 64, 0.0, 1.0};  // left half at z = 0.5 (window)
  r.draw(s, Primitive::Quads, full_quad(0.f));
  s.viewport = {0, 0, 64, 64, 0.0, 1.0};
  s.sample_counter = std::make_shared<SampleCounter>();
  r.draw(s, Primitive::Quads, full_quad(0.5f));  // behind the left half
  r.flush();
  EXPECT_EQ(s.sample_counter->passed.load(), 32u * 64u);

  auto stencil_counter = std::make_shared<SampleCounter>();
  s.depth_test = false;
  s.stencil_test = true;
  s.stencil_front.func = s.stencil_back.func = CompareFunc::Equal;  // stencil is 0: all pass
  s.stencil_front.ref = s.stencil_back.ref = 1;
  s.scissor_test = true;
  s.scissor = {0, 0, 10, 10};
  s.sample_counter = stencil_counter;
  r.draw(s, Primitive::Quads, full_quad(0.f));
  r.flush();
  EXPECT_EQ(stencil_counter->passed.load(), 0u);
}

TEST(SampleCounter, AlphaTestFailuresAreNotCounted) {
  OwnedFramebuffer fb(16, 16);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  DrawState s = state_for(16, 16);
  s.alpha_test = true;
  s.alpha_func = CompareFunc::Greater;
  s.alpha_ref = 0.5f;
  s.sample_counter = std::make_shared<SampleCounter>();
  std::vector<ClipVertex> v = full_quad(0.f);
  for (ClipVertex& c : v) c.color[3] = c.back_color[3] = 0.25f;
  r.draw(s, Primitive::Quads, v);
  r.flush();
  EXPECT_EQ(s.sample_counter->passed.load(), 0u);
}

uint64_t count_busy_scene(int threads) {
  OwnedFramebuffer fb(300, 211);
  Renderer r(threads);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  auto counter = std::make_shared<SampleCounter>();
  for (int i = 0; i < 200; ++i) {
    DrawState s = state_for(300, 211);
    s.depth_test = true;
    s.sample_counter = counter;
    const float o = static_cast<float>(i % 17) / 17.f - 0.5f, z = static_cast<float>(i % 13) / 13.f - 0.5f;
    std::vector<ClipVertex> v{vertex(-1 + o, -1, z), vertex(1, -1 - o, -z), vertex(o, 1, z)};
    r.draw(s, Primitive::Triangles, v);
  }
  r.flush();
  return counter->passed.load();
}

TEST(SampleCounter, SameSumForAnyThreadCount) {
  const uint64_t one = count_busy_scene(1);
  EXPECT_GT(one, 300u * 211u);
  EXPECT_EQ(one, count_busy_scene(2));
  EXPECT_EQ(one, count_busy_scene(5));
}

TEST(SampleCounter, DrawsWithoutCounterUseTheUncountedRoutine) {
  DrawState s = state_for(8, 8);
  OwnedFramebuffer fb(8, 8);
  const DrawRecord plain = make_draw_record(s, fb.fb);
  s.sample_counter = std::make_shared<SampleCounter>();
  const DrawRecord counting = make_draw_record(s, fb.fb);
  EXPECT_FALSE(plain.key.count_samples);
  EXPECT_TRUE(counting.key.count_samples);
  EXPECT_NE(plain.routine, counting.routine);
}

}  // namespace
}  // namespace pineda::raster::test
