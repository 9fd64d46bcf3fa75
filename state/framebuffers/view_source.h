// What a framebuffer object's view (framebuffer_views.cpp) is built from, as words: every
// attachment's description, the object and storage it resolves to (with the texture's change
// count) and the buffers. A view built from equal sources is the same view, so a draw into an
// unchanged framebuffer keeps its view instead of rebuilding it.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace pineda {

class ViewSource {
 public:
  void add(uint64_t word) {
    if (count_ < words_.size()) words_[count_] = word;
    ++count_;  // past the array: never equal (below)
  }
  void add(const void* p) { add(static_cast<uint64_t>(reinterpret_cast<uintptr_t>(p))); }

  bool operator==(const ViewSource& other) const {
    return count_ <= words_.size() && count_ == other.count_ &&
           std::equal(words_.begin(), words_.begin() + static_cast<std::ptrdiff_t>(count_), other.words_.begin());
  }

 private:
  std::array<uint64_t, 256> words_{};
  size_t count_ = 0;
};

}  // namespace pineda
