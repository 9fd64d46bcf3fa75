#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "raster/worker_pool.h"

namespace pineda::raster {
namespace {

TEST(WorkerPool, RunsEveryItemExactlyOnceAcrossManyJobs) {
  for (const int threads : {1, 2, 4}) {
    WorkerPool pool(threads);
    EXPECT_EQ(pool.threads(), threads);
    for (int job = 0; job < 50; ++job) {
      std::vector<std::atomic<int>> hits(97 + job);
      pool.run(static_cast<int>(hits.size()), [&](int i) { hits[i].fetch_add(1); });
      for (auto& h : hits) ASSERT_EQ(h.load(), 1);
    }
    pool.run(0, [](int) { FAIL(); });
  }
}

TEST(WorkerPool, ThreadCountFromArgumentOrEnvironment) {
  EXPECT_EQ(resolve_thread_count(3), 3);
  EXPECT_GE(resolve_thread_count(0), 1);
}

}  // namespace
}  // namespace pineda::raster
