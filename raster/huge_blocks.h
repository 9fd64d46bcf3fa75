// Memory for large buffers (framebuffers, texture levels, the vertex and scene stores) in
// blocks of their own mapping, starting on a 2 MiB boundary, rounded up to whole 2 MiB and
// advised for transparent huge pages. A first write to a 4 KiB page is a page fault, and in a
// virtual machine a costly one: on this project's VM 64 MiB first touched in small pages took
// 265 ms, in huge pages 6 ms. Buffers that are new in a program's first frame made it 1.5 to 4
// times as long as the next. Where the kernel gives no huge page (THP off, memory fragmented),
// the block is the same memory in small pages.
#pragma once
#include <cstddef>

namespace pineda::raster {

constexpr size_t kHugePageBytes = size_t{2} << 20;

// `bytes` (> 0) zero-filled bytes at a 2 MiB boundary. Throws std::bad_alloc when refused.
void* map_huge_block(size_t bytes);
// Unmaps what map_huge_block(bytes) or take_huge_block(bytes) returned (null: nothing).
void unmap_huge_block(void* block, size_t bytes) noexcept;

// For blocks released and taken again from frame to frame (a texture respecified every frame,
// a snapshot rebuilt after every render into its texture): a block of the same size released
// lately, its contents left as they were, or a new one. A new mapping's huge pages are zeroed
// by the kernel at their first touch (0.35 ms for 4 MiB measured, where a heap block used again
// costs nothing), so the process keeps the last few released blocks.
void* take_huge_block(size_t bytes);
// Keeps the block for take_huge_block, unmapping the one kept longest when too many are kept.
void release_huge_block(void* block, size_t bytes) noexcept;

}  // namespace pineda::raster
