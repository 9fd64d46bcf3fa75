// Client memory of which only one window can be read: a large reserved range of addresses
// whose pages are inaccessible except those holding [offset, offset + size). A GL call that
// reads outside the window faults, so a test shows that a call reads only the bytes its
// arguments allow, even when its unpack skips put them gigabytes past the pointer.
#pragma once
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>

namespace pineda::test {

class GuardedMemory {
 public:
  // `reserved` bytes of addresses from base(); bytes [offset, offset + size) are readable and
  // writable (with the rest of their pages).
  GuardedMemory(size_t reserved, size_t offset, size_t size) : reserved_(reserved) {
    void* p = mmap(nullptr, reserved, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (p == MAP_FAILED) return;
    base_ = static_cast<uint8_t*>(p);
    const size_t page = size_t(sysconf(_SC_PAGESIZE));
    const size_t first = offset / page * page;
    const size_t last = (offset + size + page - 1) / page * page;
    if (mprotect(base_ + first, last - first, PROT_READ | PROT_WRITE) != 0) {
      munmap(base_, reserved_);
      base_ = nullptr;
    }
  }
  ~GuardedMemory() {
    if (base_) munmap(base_, reserved_);
  }
  GuardedMemory(const GuardedMemory&) = delete;
  GuardedMemory& operator=(const GuardedMemory&) = delete;

  bool ok() const { return base_ != nullptr; }
  uint8_t* base() const { return base_; }

 private:
  uint8_t* base_ = nullptr;
  size_t reserved_;
};

}  // namespace pineda::test
