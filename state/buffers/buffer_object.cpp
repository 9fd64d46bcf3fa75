#include "state/buffers/buffer_object.h"

namespace pineda {

const uint8_t* buffer_range(const BufferObject& buffer, uintptr_t offset, size_t size) {
  const size_t total = buffer.data.size();
  if (offset > total || size > total - offset) return nullptr;
  return buffer.data.data() + offset;
}

}  // namespace pineda
