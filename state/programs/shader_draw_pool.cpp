#include "state/programs/shader_draw_pool.h"

#include <atomic>

namespace pineda {
namespace {

// How many kept ShaderDraws take() looks at before it makes a new one.
constexpr int kLooks = 4;

}  // namespace

std::shared_ptr<raster::ShaderDraw> ShaderDrawPool::take(size_t uniform_floats) {
  if (uniform_floats > kMaxKeptUniformFloats) return std::make_shared<raster::ShaderDraw>();
  for (int look = 0; look < kLooks && !kept_.empty(); ++look) {
    std::shared_ptr<raster::ShaderDraw>& kept = kept_[next_];
    next_ = (next_ + 1) % kept_.size();
    // Only this context's thread makes references to a kept ShaderDraw (from the pool's own);
    // other threads only let theirs go. A count of one is then final; the fence orders the last
    // holder's reads of it before the writes of its next use.
    if (kept.use_count() != 1) continue;
    std::atomic_thread_fence(std::memory_order_acquire);
    kept->prepare_for_reuse();
    return kept;
  }
  auto made = std::make_shared<raster::ShaderDraw>();
  if (kept_.size() < kMaxKept) kept_.push_back(made);
  return made;
}

}  // namespace pineda
