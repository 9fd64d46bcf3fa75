#include "raster/huge_blocks.h"

#include <sys/mman.h>

#include <cstdint>
#include <new>

namespace pineda::raster {
namespace {

// `bytes` in whole huge pages (0 when that does not fit a size_t).
size_t whole_huge_pages(size_t bytes) {
  const size_t rounded = (bytes + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  return rounded < bytes ? 0 : rounded;
}

}  // namespace

void* map_huge_block(size_t bytes) {
  const size_t size = whole_huge_pages(bytes);
  if (size == 0 || size > SIZE_MAX - kHugePageBytes) throw std::bad_alloc();
  // One huge page more than needed, then trimmed to start on a huge-page boundary.
  void* raw = mmap(nullptr, size + kHugePageBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const uintptr_t start = reinterpret_cast<uintptr_t>(raw);
  const uintptr_t block = (start + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
  const uintptr_t end = start + size + kHugePageBytes;
  if (block > start) munmap(raw, block - start);
  if (end > block + size) munmap(reinterpret_cast<void*>(block + size), end - (block + size));
  madvise(reinterpret_cast<void*>(block), size, MADV_HUGEPAGE);  // only advice: refused, the pages stay small
  return reinterpret_cast<void*>(block);
}

void unmap_huge_block(void* block, size_t bytes) noexcept {
  if (block) munmap(block, whole_huge_pages(bytes));
}

}  // namespace pineda::raster
