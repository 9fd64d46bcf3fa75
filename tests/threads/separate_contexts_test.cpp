// N threads, each with its own context, render the scene at once: every thread's images,
// frame by frame, are byte-identical to those one thread renders alone; for each window-system
// API and for 1, 2 and 3 rasterizer worker threads per context (PINEDA_THREADS).
#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <tuple>

#include "tests/threads/thread_runs.h"

namespace pineda::threads_test {
namespace {

class SeparateContexts : public ::testing::TestWithParam<std::tuple<Api, const char*>> {};

TEST_P(SeparateContexts, EveryThreadRendersTheImagesOfOneThreadAlone) {
  const auto [api, workers] = GetParam();
  if (!api_available(api)) GTEST_SKIP() << "no X display (DISPLAY)";
  WorkerThreadsSetting setting(workers);
  const int frames = frames_per_thread();
  const std::vector<ThreadRun> alone = run_threads(api, 1, frames);
  ASSERT_EQ(alone[0].error, "");
  ASSERT_EQ(alone[0].hashes.size(), size_t(frames));
  // The scene moves from frame to frame and is not flat: a wrong image cannot pass unseen.
  EXPECT_EQ(std::set<uint64_t>(alone[0].hashes.begin(), alone[0].hashes.end()).size(), size_t(frames));
  std::set<uint32_t> colours;
  for (size_t i = 0; i + 3 < alone[0].last_image.size(); i += 4) {
    const uint8_t* p = &alone[0].last_image[i];
    colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
  }
  EXPECT_GT(colours.size(), 500u);
  std::printf("%s, %s worker threads: %d frames alone, %zu colours in the last, its hash %016llx\n",
              api_name(api).c_str(), workers, frames, colours.size(), static_cast<unsigned long long>(alone[0].hashes.back()));
  for (int threads : {1, 2, 8}) {
    const std::vector<ThreadRun> runs = run_threads(api, threads, frames);
    for (int t = 0; t < threads; ++t) {
      SCOPED_TRACE(testing::Message() << threads << " threads, thread " << t);
      EXPECT_EQ(runs[t].error, "");
      EXPECT_EQ(runs[t].hashes, alone[0].hashes);
      EXPECT_EQ(runs[t].last_image, alone[0].last_image);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ApisAndWorkers, SeparateContexts,
                         ::testing::Combine(::testing::Values(Api::EglPbuffer, Api::EglSurfaceless, Api::OSMesa, Api::GlxPbuffer),
                                            ::testing::Values("1", "2", "3")),
                         [](const auto& info) {
                           return api_name(std::get<0>(info.param)) + "_Workers" + std::get<1>(info.param);
                         });

}  // namespace
}  // namespace pineda::threads_test
