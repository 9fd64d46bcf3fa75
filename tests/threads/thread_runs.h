// Runs the scene on several threads at once, each through its own context, and collects
// what each thread saw.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "tests/threads/scene.h"
#include "tests/threads/test_context.h"

namespace pineda::threads_test {

struct ThreadRun {
  std::string error;             // empty when the thread could render
  std::vector<uint64_t> hashes;  // one per frame
  std::vector<uint8_t> last_image;
};

// Frames each thread renders: PINEDA_THREADS_TEST_FRAMES, or 40.
int frames_per_thread();

// `threads` threads start together; each makes a context of `api` (sharing with `share` and
// drawing its objects `shared` if given, otherwise creating its own), renders the frames
// and destroys the context.
std::vector<ThreadRun> run_threads(Api api, int threads, int frames, const TestContext* share = nullptr,
                                   const SceneObjects* shared = nullptr);

// Sets PINEDA_THREADS (rasterizer workers of the contexts created afterwards) for its lifetime.
class WorkerThreadsSetting {
 public:
  explicit WorkerThreadsSetting(const char* value);
  ~WorkerThreadsSetting();

 private:
  std::string old_;
  bool had_old_ = false;
};

}  // namespace pineda::threads_test
