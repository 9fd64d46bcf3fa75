// Contexts of one share group (EGL share_context, OSMesa sharelist) draw with one shared
// texture, buffer object and program from several threads at once: each thread's images are
// byte-identical to those of one thread drawing with them alone.
#include <gtest/gtest.h>

#include "tests/threads/thread_runs.h"

namespace pineda::threads_test {
namespace {

class SharedObjects : public ::testing::TestWithParam<Api> {};

TEST_P(SharedObjects, ThreadsDrawingSharedObjectsAtOnceRenderTheImagesOfOneAlone) {
  const Api api = GetParam();
  if (!api_available(api)) GTEST_SKIP() << "no X display (DISPLAY)";
  TestContext owner(api, kWidth, kHeight);
  ASSERT_TRUE(owner.ok() && owner.make_current());
  const SceneObjects shared = create_scene_objects();
  ASSERT_NE(shared.program, 0u);
  owner.release();

  const int frames = frames_per_thread();
  const std::vector<ThreadRun> alone = run_threads(api, 1, frames, &owner, &shared);
  ASSERT_EQ(alone[0].error, "");
  ASSERT_EQ(alone[0].hashes.size(), size_t(frames));
  // The objects are the ones a context of its own creates: the same images.
  const std::vector<ThreadRun> own = run_threads(api, 1, frames);
  EXPECT_EQ(own[0].hashes, alone[0].hashes);
  for (int threads : {2, 8}) {
    const std::vector<ThreadRun> runs = run_threads(api, threads, frames, &owner, &shared);
    for (int t = 0; t < threads; ++t) {
      SCOPED_TRACE(testing::Message() << threads << " threads, thread " << t);
      EXPECT_EQ(runs[t].error, "");
      EXPECT_EQ(runs[t].hashes, alone[0].hashes);
      EXPECT_EQ(runs[t].last_image, alone[0].last_image);
    }
  }
  ASSERT_TRUE(owner.make_current());
  delete_scene_objects(shared);
  owner.release();
}

INSTANTIATE_TEST_SUITE_P(Apis, SharedObjects, ::testing::Values(Api::EglPbuffer, Api::EglSurfaceless, Api::OSMesa, Api::GlxPbuffer),
                         [](const auto& info) { return api_name(info.param); });

}  // namespace
}  // namespace pineda::threads_test
