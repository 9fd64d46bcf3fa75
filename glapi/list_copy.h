// A copy of an array argument taken when a call is compiled into a display list: GL reads
// the application's memory at compile time, not when the list runs.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

namespace pineda::glapi {

template <typename T>
class ListCopy {
 public:
  ListCopy(const T* source, size_t count) {
    if (source) values_ = std::make_shared<const std::vector<T>>(source, source + count);
  }
  // Null when the application passed null.
  const T* get() const { return values_ ? values_->data() : nullptr; }

 private:
  std::shared_ptr<const std::vector<T>> values_;
};

}  // namespace pineda::glapi
