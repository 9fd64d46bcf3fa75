// The memory of a renderer's draw records (Scene::begin_draw), in slabs: a record is 1.8 KiB,
// and a frame of thousands of draws took them from a heap that grew page by page in its first
// frame (state_changes' first frame makes 6,144 records in 11 MiB of new heap: 23.1 ms before
// the huge blocks and this pool, 16.9 with both, in runs side by side). A slab after the first
// is a huge block (huge_blocks.h). Records released on any thread (a band's scene drops its
// commands on its own) return to the pool; the pool lives until its renderer and the last record
// are gone: its owner's handle and each piece taken hold a reference. (The allocator held a
// shared_ptr to the pool, whose copies inside allocate_shared were three atomic increments and
// decrements a record once the pool's threads exist: glsl_many_draws 4% slower with two threads.)
#pragma once
#include <atomic>
#include <cstddef>
#include <memory>
#include <mutex>
#include <new>
#include <utility>
#include <vector>

#include "raster/draw_record.h"

namespace pineda::raster {

class RecordPool {
 public:
  RecordPool() = default;  // with its owner's reference
  RecordPool(const RecordPool&) = delete;
  RecordPool& operator=(const RecordPool&) = delete;

  // `bytes` bytes aligned for any record: a piece of a slab when `bytes` is the pool's piece
  // size (set by the first request), else from operator new. Throws std::bad_alloc.
  void* take(size_t bytes);
  void give_back(void* piece, size_t bytes) noexcept;
  // The owner's reference goes (RecordPoolHandle); the pool goes with the last reference.
  void drop_reference() noexcept;

 private:
  ~RecordPool();
  bool is_piece(size_t bytes) const;  // these and the rest: with mutex_ held
  void add_slab();

  struct Slab {
    void* block;
    bool huge;
  };
  std::atomic<size_t> references_{1};
  std::mutex mutex_;
  size_t piece_bytes_ = 0;
  size_t pieces_ = 0;  // in all slabs; free_ has room for all, so that give_back never allocates
  std::vector<void*> free_;
  std::vector<Slab> slabs_;
};

struct RecordPoolRelease {
  void operator()(RecordPool* pool) const noexcept { pool->drop_reference(); }
};
// The renderer's hold on its pool.
using RecordPoolHandle = std::unique_ptr<RecordPool, RecordPoolRelease>;
inline RecordPoolHandle make_record_pool() { return RecordPoolHandle(new RecordPool); }

// The allocator allocate_shared uses for a record and its count: the pool's pieces (each piece
// holds a reference to the pool; the allocator's copies hold none).
template <typename T>
struct RecordPoolAllocator {
  using value_type = T;
  RecordPool* pool;

  explicit RecordPoolAllocator(RecordPool* p) noexcept : pool(p) {}
  template <typename U>
  RecordPoolAllocator(const RecordPoolAllocator<U>& other) noexcept : pool(other.pool) {}

  T* allocate(size_t n) {
    if (n > static_cast<size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    return static_cast<T*>(pool->take(n * sizeof(T)));
  }
  void deallocate(T* p, size_t n) noexcept { pool->give_back(p, n * sizeof(T)); }
  template <typename U>
  bool operator==(const RecordPoolAllocator<U>& other) const noexcept {
    return pool == other.pool;
  }
};

// A shared record in `pool`'s memory.
inline std::shared_ptr<const DrawRecord> make_pooled_record(RecordPool* pool, DrawRecord&& record) {
  return std::allocate_shared<const DrawRecord>(RecordPoolAllocator<DrawRecord>(pool), std::move(record));
}

}  // namespace pineda::raster
