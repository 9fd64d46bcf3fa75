#include "raster/worker_pool.h"

#include <algorithm>
#include <cstdlib>

namespace pineda::raster {

int resolve_thread_count(int threads) {
  if (threads > 0) return std::min(threads, 256);
  if (const char* env = std::getenv("PINEDA_THREADS")) {
    const int n = std::atoi(env);
    if (n > 0) return std::min(n, 256);
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

WorkerPool::WorkerPool(int threads) {
  for (int i = 1; i < threads; ++i) workers_.emplace_back([this] { worker_loop(); });
}

WorkerPool::~WorkerPool() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

// Takes items until none is left; `lock` holds the mutex on entry and on return.
void WorkerPool::drain(std::unique_lock<std::mutex>& lock) {
  while (next_ < count_) {
    const int i = next_++;
    lock.unlock();
    job_(i);  // not reassigned before every item is finished (wait)
    lock.lock();
    if (++finished_ == count_) done_.notify_all();
  }
}

void WorkerPool::worker_loop() {
  uint64_t seen = 0;
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stop_ || generation_ != seen; });
    if (stop_) return;
    seen = generation_;
    drain(lock);
  }
}

void WorkerPool::run(int count, std::function<void(int)> fn) {
  if (count <= 0) return;
  if (workers_.empty() || count == 1) {
    for (int i = 0; i < count; ++i) fn(i);
    return;
  }
  start(count, std::move(fn));
  wait();
}

void WorkerPool::start(int count, std::function<void(int)> fn) {
  std::unique_lock lock(mutex_);
  job_ = std::move(fn);
  count_ = std::max(count, 0);
  next_ = 0;
  finished_ = 0;
  ++generation_;
  wake_.notify_all();
}

void WorkerPool::wait() {
  std::unique_lock lock(mutex_);
  drain(lock);
  done_.wait(lock, [&] { return finished_ == count_; });
  job_ = nullptr;
  count_ = 0;
  next_ = 0;
  finished_ = 0;
}

bool WorkerPool::finished() {
  std::lock_guard lock(mutex_);
  return finished_ == count_;
}

}  // namespace pineda::raster
