#include "state/transformed_vertices.h"

#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>

namespace pineda {
namespace {

// Asks for 2 MiB pages over the whole 2 MiB pieces of a large store: one page fault (and one
// kernel clear) per 2 MiB rather than per 4 KiB when the vertex stage first writes it.
void prefer_huge_pages(void* p, size_t bytes) {
  constexpr uintptr_t kHuge = uintptr_t{2} << 20;
  const auto begin = (reinterpret_cast<uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const auto end = (reinterpret_cast<uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

}  // namespace

void TransformedVertices::Release::operator()(raster::ClipVertex* p) const { std::free(p); }

std::span<raster::ClipVertex> TransformedVertices::resize(size_t count) {
  static_assert(std::is_trivially_copyable_v<raster::ClipVertex> && std::is_trivially_destructible_v<raster::ClipVertex>);
  if (capacity_ < count) {
    // calloc's large blocks are fresh pages, zero without a pass over them; the vertices, an
    // implicit-lifetime type, begin their lives there.
    auto* grown = static_cast<raster::ClipVertex*>(std::calloc(count, sizeof(raster::ClipVertex)));
    if (!grown) throw std::bad_alloc();
    prefer_huge_pages(grown, count * sizeof(raster::ClipVertex));
    if (capacity_) std::memcpy(static_cast<void*>(grown), store_.get(), capacity_ * sizeof(raster::ClipVertex));
    store_.reset(grown);
    capacity_ = count;
  }
  count_ = count;
  return vertices();
}

}  // namespace pineda
