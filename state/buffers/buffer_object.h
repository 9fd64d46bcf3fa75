// Vertex buffer objects (GL 1.5): the data store, its mapping, and the context's bindings.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "state/object_names.h"

namespace pineda {

struct BufferObject {
  explicit BufferObject(GLuint n) : name(n) {}
  GLuint name;
  std::vector<uint8_t> data;
  GLenum usage = GL_STATIC_DRAW;
  GLenum access = GL_READ_WRITE;
  bool mapped = false;
  // The mapped range (glMapBuffer maps the whole store) and its GL_MAP_*_BIT flags
  // (GL_ARB_map_buffer_range; GL_BUFFER_ACCESS_FLAGS, GL_BUFFER_MAP_OFFSET, GL_BUFFER_MAP_LENGTH).
  GLbitfield access_flags = 0;
  size_t map_offset = 0, map_length = 0;

  void map(size_t offset, size_t length, GLbitfield flags) {
    mapped = true;
    map_offset = offset;
    map_length = length;
    access_flags = flags;
  }
  void unmap() {
    mapped = false;
    map_offset = map_length = 0;
    access_flags = 0;
  }
};

struct BufferState {
  explicit BufferState(ObjectNames<BufferObject>& shared_names) : names(shared_names) {}
  ObjectNames<BufferObject>& names;  // the share group's
  std::shared_ptr<BufferObject> array, element_array;  // GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER
  // GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER (GL_ARB_copy_buffer): bound for copies alone.
  std::shared_ptr<BufferObject> copy_read, copy_write;
};

// The `size` bytes at `offset` in the buffer's store, or null when they are not all inside it.
const uint8_t* buffer_range(const BufferObject& buffer, uintptr_t offset, size_t size);
// How many elements of `bytes` bytes, `stride` apart from `offset` on, buffer_range finds inside
// the store: element i is when offset + stride * i + bytes <= its size (SIZE_MAX with stride 0).
size_t elements_inside(const BufferObject& buffer, uintptr_t offset, size_t stride, size_t bytes);

inline GLuint buffer_name(const std::shared_ptr<BufferObject>& b) { return b ? b->name : 0; }

}  // namespace pineda
