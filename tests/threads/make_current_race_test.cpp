// Several threads try at once, over and over, to make one context current: a context is
// current to at most one thread at a time, and every refusal is the one the API specifies
// (EGL_BAD_ACCESS; OSMesa returns GL_FALSE). Whoever holds it renders the scene's image.
#define EGL_EGLEXT_PROTOTYPES
#include <EGL/egl.h>
#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "tests/threads/thread_runs.h"

namespace pineda::threads_test {
namespace {

class MakeCurrentRace : public ::testing::TestWithParam<Api> {};

TEST_P(MakeCurrentRace, OneThreadAtATimeHoldsAContext) {
  const Api api = GetParam();
  TestContext context(api, kWidth, kHeight);
  ASSERT_TRUE(context.ok() && context.make_current());
  const SceneObjects objects = create_scene_objects();
  const uint64_t expected = image_hash(render_frame(objects, 3));
  context.release();

  constexpr int kThreads = 8, kAttempts = 40;
  std::atomic<int> holders{0}, overlaps{0}, successes{0}, refusals{0}, wrong_errors{0}, wrong_images{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < kThreads; ++t)
    pool.emplace_back([&] {
      for (int i = 0; i < kAttempts; ++i) {
        if (!context.make_current()) {
          refusals.fetch_add(1);
          if (api != Api::OSMesa && eglGetError() != EGL_BAD_ACCESS) wrong_errors.fetch_add(1);
          std::this_thread::yield();
          continue;
        }
        if (holders.fetch_add(1) != 0) overlaps.fetch_add(1);
        successes.fetch_add(1);
        if (image_hash(render_frame(objects, 3)) != expected) wrong_images.fetch_add(1);
        holders.fetch_sub(1);
        context.release();
      }
      if (api != Api::OSMesa) eglReleaseThread();
    });
  for (std::thread& t : pool) t.join();
  EXPECT_EQ(overlaps.load(), 0);
  EXPECT_EQ(wrong_errors.load(), 0);
  EXPECT_EQ(wrong_images.load(), 0);
  EXPECT_GT(successes.load(), 0);
  EXPECT_EQ(successes.load() + refusals.load(), kThreads * kAttempts);
  std::printf("%s: %d bindings, %d refused\n", api_name(api).c_str(), successes.load(), refusals.load());

  ASSERT_TRUE(context.make_current());
  delete_scene_objects(objects);
  context.release();
}

INSTANTIATE_TEST_SUITE_P(Apis, MakeCurrentRace, ::testing::Values(Api::EglPbuffer, Api::EglSurfaceless, Api::OSMesa),
                         [](const auto& info) { return api_name(info.param); });

}  // namespace
}  // namespace pineda::threads_test
