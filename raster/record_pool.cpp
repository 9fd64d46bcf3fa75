#include "raster/record_pool.h"

#include <cstddef>

#include "raster/huge_blocks.h"

namespace pineda::raster {
namespace {

constexpr size_t kFirstSlabBytes = size_t{64} << 10;  // a program of a few draws maps no huge page
constexpr size_t kPieceAlignment = 64;
static_assert(kPieceAlignment >= alignof(std::max_align_t) && kPieceAlignment >= alignof(DrawRecord));

size_t piece_size(size_t bytes) { return (bytes + kPieceAlignment - 1) & ~(kPieceAlignment - 1); }

}  // namespace

RecordPool::~RecordPool() {
  for (const Slab& slab : slabs_) {
    if (slab.huge) unmap_huge_block(slab.block, kHugePageBytes);
    else ::operator delete(slab.block, std::align_val_t{kPieceAlignment});
  }
}

bool RecordPool::is_piece(size_t bytes) const {
  return piece_size(bytes) == piece_bytes_;
}

void* RecordPool::take(size_t bytes) {
  void* piece = nullptr;
  {
    std::lock_guard lock(mutex_);
    if (piece_bytes_ == 0) piece_bytes_ = piece_size(bytes);
    if (is_piece(bytes)) {
      if (free_.empty()) add_slab();
      piece = free_.back();
      free_.pop_back();
    }
  }
  if (!piece) piece = ::operator new(bytes, std::align_val_t{kPieceAlignment});
  references_.fetch_add(1, std::memory_order_relaxed);  // (the taker holds one already)
  return piece;
}

void RecordPool::give_back(void* piece, size_t bytes) noexcept {
  if (!piece) return;
  bool kept;
  {
    std::lock_guard lock(mutex_);
    kept = is_piece(bytes);
    if (kept) free_.push_back(piece);
  }
  if (!kept) ::operator delete(piece, std::align_val_t{kPieceAlignment});
  drop_reference();
}

void RecordPool::drop_reference() noexcept {
  if (references_.fetch_sub(1, std::memory_order_acq_rel) == 1) delete this;
}

void RecordPool::add_slab() {
  const bool huge = !slabs_.empty();
  const size_t bytes = huge ? kHugePageBytes : kFirstSlabBytes;
  const size_t pieces = bytes / piece_bytes_;
  if (pieces == 0) throw std::bad_alloc();
  slabs_.reserve(slabs_.size() + 1);
  free_.reserve(pieces_ + pieces);
  void* block = huge ? map_huge_block(bytes) : ::operator new(bytes, std::align_val_t{kPieceAlignment});
  slabs_.push_back({block, huge});
  pieces_ += pieces;
  for (size_t k = pieces; k-- > 0;) free_.push_back(static_cast<char*>(block) + k * piece_bytes_);
}

}  // namespace pineda::raster
