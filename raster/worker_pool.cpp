#include "raster/worker_pool.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

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

namespace {

// How long a thread polls before it blocks: longer than binning one scene of small triangles
// takes (about 100 us for a thousand on this VM), short enough to cost little when idle.
constexpr std::chrono::microseconds kPollFor{200};

}  // namespace

template <class Ready>
bool WorkerPool::poll_briefly(const Ready& ready) {
  const auto until = std::chrono::steady_clock::now() + kPollFor;
  for (;;) {
    for (int i = 0; i < 64; ++i) {
      if (ready()) return true;
#if defined(__x86_64__) || defined(__i386__)
      _mm_pause();
#endif
    }
    if (std::chrono::steady_clock::now() >= until) return ready();
  }
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
    auto ready = [&] { return stop_.load(std::memory_order_acquire) || generation_.load(std::memory_order_acquire) != seen; };
    lock.unlock();
    poll_briefly(ready);
    lock.lock();
    if (!ready()) {
      ++sleeping_;
      wake_.wait(lock, ready);
      --sleeping_;
    }
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
  generation_.fetch_add(1, std::memory_order_release);
  if (sleeping_ > 0) wake_.notify_all();
}

void WorkerPool::wait() {
  std::unique_lock lock(mutex_);
  drain(lock);
  const int count = count_;
  auto done = [&] { return finished_.load(std::memory_order_acquire) == count; };
  if (!done()) {
    lock.unlock();
    poll_briefly(done);
    lock.lock();
    done_.wait(lock, done);
  }
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
