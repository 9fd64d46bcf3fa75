#include "raster/huge_blocks.h"

#include <sys/mman.h>

#include <cstdint>
#include <mutex>
#include <new>

namespace pineda::raster {
namespace {

// `n` (a size or an address) rounded up to a whole number of huge pages (0 when that does not
// fit a size_t).
size_t huge_page_ceiling(size_t n) {
  const size_t rounded = (n + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  return rounded < n ? 0 : rounded;
}

struct Block {
  void* start = nullptr;
  size_t size = 0;  // whole huge pages
};

// The blocks released for take_huge_block: the process's, as the heap's free memory is (a block
// may be released by another context, or on a worker thread). At most kMaxBlocks blocks of
// kMaxBytes in all; the one released longest ago goes first.
class KeptBlocks {
 public:
  void* take(size_t size) {
    std::lock_guard lock(mutex_);
    for (int i = count_ - 1; i >= 0; --i)
      if (kept_[i].size == size) return remove(i).start;
    return nullptr;
  }
  // Keeps `block`, unmapping those released longest ago while there are too many.
  void keep(Block block) {
    if (block.size > kMaxBytes) return release(block);
    std::lock_guard lock(mutex_);
    size_t total = block.size;
    for (int i = 0; i < count_; ++i) total += kept_[i].size;
    while (count_ > 0 && (count_ == kMaxBlocks || total > kMaxBytes)) {
      const Block eldest = remove(0);
      total -= eldest.size;
      release(eldest);
    }
    kept_[count_++] = block;
  }

 private:
  static void release(Block block) { munmap(block.start, block.size); }
  Block remove(int i) {  // with mutex_ held
    const Block removed = kept_[i];
    for (int j = i; j + 1 < count_; ++j) kept_[j] = kept_[j + 1];
    --count_;
    return removed;
  }

  static constexpr int kMaxBlocks = 4;
  static constexpr size_t kMaxBytes = size_t{32} << 20;
  std::mutex mutex_;
  Block kept_[kMaxBlocks];
  int count_ = 0;
};

KeptBlocks& kept_blocks() {
  static KeptBlocks* const kept = new KeptBlocks;  // never destroyed: vectors may outlive static destructors
  return *kept;
}

}  // namespace

void* map_huge_block(size_t bytes) {
  const size_t size = huge_page_ceiling(bytes);
  if (size == 0 || size > SIZE_MAX - kHugePageBytes) throw std::bad_alloc();
  // One huge page more than needed, then trimmed to start on a huge-page boundary.
  void* raw = mmap(nullptr, size + kHugePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const uintptr_t start = reinterpret_cast<uintptr_t>(raw);
  const uintptr_t block = huge_page_ceiling(start);
  const uintptr_t end = start + size + kHugePageBytes;
  if (block > start) munmap(raw, block - start);
  if (end > block + size) munmap(reinterpret_cast<void*>(block + size), end - (block + size));
  madvise(reinterpret_cast<void*>(block), size, MADV_HUGEPAGE);  // only advice: refused, the pages stay small
  return reinterpret_cast<void*>(block);
}

void unmap_huge_block(void* block, size_t bytes) noexcept {
  if (block) munmap(block, huge_page_ceiling(bytes));
}

void* take_huge_block(size_t bytes) {
  if (void* kept = kept_blocks().take(huge_page_ceiling(bytes))) return kept;
  return map_huge_block(bytes);
}

void release_huge_block(void* block, size_t bytes) noexcept {
  if (!block) return;
  kept_blocks().keep({block, huge_page_ceiling(bytes)});
}

}  // namespace pineda::raster
