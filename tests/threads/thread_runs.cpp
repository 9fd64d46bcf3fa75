#include "tests/threads/thread_runs.h"

#include <GL/gl.h>

#include <atomic>
#include <cstdlib>
#include <thread>

namespace pineda::threads_test {

int frames_per_thread() {
  const char* env = std::getenv("PINEDA_THREADS_TEST_FRAMES");
  const int frames = env ? std::atoi(env) : 0;
  return frames > 0 ? frames : 40;
}

namespace {

void render_on_this_thread(Api api, int frames, const TestContext* share, const SceneObjects* shared,
                           std::atomic<int>& ready, int threads, ThreadRun& run) {
  TestContext context(api, kWidth, kHeight, share);
  const bool current = context.ok() && context.make_current();
  SceneObjects own;
  if (current && !shared) own = create_scene_objects();
  // Every thread has made its context before any renders, so that they all render at once.
  ready.fetch_add(1);
  while (ready.load() < threads) std::this_thread::yield();
  if (!current) {
    run.error = api_name(api) + ": no current context";
    return;
  }
  const SceneObjects& objects = shared ? *shared : own;
  if (!objects.program) run.error = "the scene's program did not link";
  for (int f = 0; f < frames; ++f) {
    std::vector<uint8_t> image = render_frame(objects, f);
    run.hashes.push_back(image_hash(image));
    if (f == frames - 1) run.last_image = std::move(image);
  }
  if (const GLenum error = glGetError(); error != GL_NO_ERROR) run.error = "GL error " + std::to_string(error);
  if (!shared) delete_scene_objects(own);
  context.release();
}

}  // namespace

std::vector<ThreadRun> run_threads(Api api, int threads, int frames, const TestContext* share,
                                   const SceneObjects* shared) {
  std::vector<ThreadRun> runs(threads);
  std::atomic<int> ready{0};
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back(render_on_this_thread, api, frames, share, shared, std::ref(ready), threads, std::ref(runs[t]));
  for (std::thread& t : pool) t.join();
  return runs;
}

WorkerThreadsSetting::WorkerThreadsSetting(const char* value) {
  if (const char* old = std::getenv("PINEDA_THREADS")) {
    old_ = old;
    had_old_ = true;
  }
  setenv("PINEDA_THREADS", value, 1);
}

WorkerThreadsSetting::~WorkerThreadsSetting() {
  if (had_old_)
    setenv("PINEDA_THREADS", old_.c_str(), 1);
  else
    unsetenv("PINEDA_THREADS");
}

}  // namespace pineda::threads_test
