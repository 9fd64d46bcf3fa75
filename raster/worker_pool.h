// A fixed set of threads that, together with the calling thread, runs the items of a job.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace pineda::raster {

class WorkerPool {
 public:
  // `threads` counts the calling thread: 1 means no extra threads.
  explicit WorkerPool(int threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()) + 1; }

  // Calls fn(i) once for each i in [0, count), on any of the threads; returns when all are done.
  void run(int count, std::function<void(int)> fn);

  // As run, but returns at once: only the pool's own threads take items until wait(), where the
  // calling thread joins them and returns when all are done. Needs threads() > 1; one job at a
  // time (start after the previous job's wait).
  void start(int count, std::function<void(int)> fn);
  void wait();
  // True when every item of the started job is finished (wait() would not block).
  bool finished();

 private:
  void worker_loop();
  void drain(std::unique_lock<std::mutex>& lock);
  // Before a thread blocks on a condition variable it polls `ready` for a short while (the
  // mutex not held): handing a job to a sleeping thread (a futex wake, then the scheduler's
  // wake-up) cost more than rasterizing a scene of a thousand small triangles on this VM.
  template <class Ready>
  static bool poll_briefly(const Ready& ready);

  std::vector<std::thread> workers_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable done_;
  std::function<void(int)> job_;
  int count_ = 0;
  int next_ = 0;
  // Written under the mutex; read without it while polling.
  std::atomic<int> finished_{0};
  std::atomic<uint64_t> generation_{0};
  std::atomic<bool> stop_{false};
  // Workers blocked on wake_ (under the mutex): start() wakes them only if there are some.
  int sleeping_ = 0;
};

// threads <= 0: PINEDA_THREADS if set to a positive number, otherwise one per core.
int resolve_thread_count(int threads);

}  // namespace pineda::raster
