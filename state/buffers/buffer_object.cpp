#include "state/buffers/buffer_object.h"

#include <cstdint>

namespace pineda {

const uint8_t* buffer_range(const BufferObject& buffer, uintptr_t offset, size_t size) {
  const size_t total = buffer.data.size();
  if (offset > total || size > total - offset) return nullptr;
  return buffer.data.data() + offset;
}

size_t elements_inside(const BufferObject& buffer, uintptr_t offset, size_t stride, size_t bytes) {
  const size_t total = buffer.data.size();
  if (offset > total || bytes > total - offset) return 0;
  return stride ? (total - offset - bytes) / stride + 1 : SIZE_MAX;
}

}  // namespace pineda
