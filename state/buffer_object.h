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
};

struct BufferState {
  explicit BufferState(ObjectNames<BufferObject>& shared_names) : names(shared_names) {}
  ObjectNames<BufferObject>& names;  // the share group's
  std::shared_ptr<BufferObject> array, element_array;  // GL_ARRAY_BUFFER, GL_ELEMENT_ARRAY_BUFFER
};

// The `size` bytes at `offset` in the buffer's store, or null when they are not all inside it.
const uint8_t* buffer_range(const BufferObject& buffer, uintptr_t offset, size_t size);

inline GLuint buffer_name(const std::shared_ptr<BufferObject>& b) { return b ? b->name : 0; }

}  // namespace pineda
