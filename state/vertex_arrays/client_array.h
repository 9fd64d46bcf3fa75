// One client vertex array's state (GL 2.1 tables 6.6-6.9): enable, format, pointer, buffer.
#pragma once
#include <GL/gl.h>

#include <memory>

#include "state/buffers/buffer_object.h"

namespace pineda {

struct ClientArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0;
  const void* pointer = nullptr;  // an offset into `buffer` when one was bound
  std::shared_ptr<BufferObject> buffer;  // GL_ARRAY_BUFFER when the pointer was set
  bool active() const { return enabled && (pointer || buffer); }
};

// A disabled array's initial state with `size` components of `type` (GL's tables 6.6-6.8).
inline ClientArray initial_array(GLint size, GLenum type = GL_FLOAT) {
  ClientArray a;
  a.size = size;
  a.type = type;
  return a;
}

}  // namespace pineda
