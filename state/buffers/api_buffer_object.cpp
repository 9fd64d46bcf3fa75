// Vertex buffer objects (GL 1.5, GL_ARB_vertex_buffer_object): names, data, mapping (also of a
// range: GL_ARB_map_buffer_range, ES's GL_EXT_map_buffer_range), copies (GL_ARB_copy_buffer), queries.
#include <algorithm>
#include <cstring>

#include "glapi/gl_entry_points.h"
#include "state/context.h"

namespace pineda::gl {
namespace {

// The binding point of `target`, or null (GL_INVALID_ENUM recorded).
std::shared_ptr<BufferObject>* binding(Context& ctx, GLenum target) {
  switch (target) {
    case GL_ARRAY_BUFFER: return &ctx.buffers.array;
    case GL_ELEMENT_ARRAY_BUFFER: return &ctx.buffers.element_array;
    case GL_PIXEL_PACK_BUFFER: if (!ctx.es1()) return &ctx.pack.buffer; break;
    case GL_PIXEL_UNPACK_BUFFER: if (!ctx.es1()) return &ctx.unpack.buffer; break;
    case GL_COPY_READ_BUFFER: if (!ctx.es1() && !ctx.es2()) return &ctx.buffers.copy_read; break;
    case GL_COPY_WRITE_BUFFER: if (!ctx.es1() && !ctx.es2()) return &ctx.buffers.copy_write; break;
    default: break;
  }
  ctx.record_error(GL_INVALID_ENUM, "target is not a buffer target");
  return nullptr;
}

// The buffer bound to `target`, or null with the error the spec names (no buffer bound:
// GL_INVALID_OPERATION).
BufferObject* bound_buffer(Context& ctx, GLenum target) {
  std::shared_ptr<BufferObject>* b = binding(ctx, target);
  if (!b) return nullptr;
  if (!*b) ctx.record_error(GL_INVALID_OPERATION, "no buffer is bound to target");
  return b->get();
}

bool valid_usage(GLenum usage) {
  switch (usage) {
    case GL_STREAM_DRAW: case GL_STREAM_READ: case GL_STREAM_COPY:
    case GL_STATIC_DRAW: case GL_STATIC_READ: case GL_STATIC_COPY:
    case GL_DYNAMIC_DRAW: case GL_DYNAMIC_READ: case GL_DYNAMIC_COPY:
      return true;
    default: return false;
  }
}

// Checks of Buffer/GetBufferSubData: a range inside the store of an unmapped buffer.
BufferObject* sub_data_buffer(Context& ctx, GLenum target, GLintptr offset, GLsizeiptr size) {
  BufferObject* b = bound_buffer(ctx, target);
  if (!b) return nullptr;
  if (offset < 0 || size < 0 || size_t(offset) > b->data.size() || size_t(size) > b->data.size() - size_t(offset)) {
    ctx.record_error(GL_INVALID_VALUE, "offset or size is negative or reaches past the buffer's end");
    return nullptr;
  }
  if (b->mapped) {
    ctx.record_error(GL_INVALID_OPERATION, "the buffer is mapped");
    return nullptr;
  }
  return b;
}

void unbind_everywhere(Context& ctx, GLuint name) {
  auto drop = [name](std::shared_ptr<BufferObject>& b) {
    if (b && b->name == name) b.reset();
  };
  drop(ctx.buffers.array);
  drop(ctx.buffers.element_array);
  drop(ctx.buffers.copy_read);
  drop(ctx.buffers.copy_write);
  drop(ctx.pack.buffer);
  drop(ctx.unpack.buffer);
  for (ClientArray* a : {&ctx.vertex_array, &ctx.color_array, &ctx.normal_array, &ctx.edge_flag_array,
                         &ctx.fog_coord_array, &ctx.secondary_color_array, &ctx.index_array,
                         &ctx.point_size_array})
    drop(a->buffer);
  for (TextureUnitState& unit : ctx.texture_units) drop(unit.texcoord_array.buffer);
  for (GenericArray& a : ctx.programs.arrays) drop(a.buffer);
}

}  // namespace

void GenBuffers(Context& ctx, GLsizei n, GLuint* buffers) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (buffers) ctx.buffers.names.generate(n, buffers);
}

void DeleteBuffers(Context& ctx, GLsizei n, const GLuint* buffers) {
  if (n < 0) return ctx.record_error(GL_INVALID_VALUE, "n is negative");
  if (!buffers) return;
  for (GLsizei i = 0; i < n; ++i) {
    if (buffers[i] == 0) continue;
    if (std::shared_ptr<BufferObject> b = ctx.buffers.names.find(buffers[i])) b->unmap();
    unbind_everywhere(ctx, buffers[i]);
    ctx.buffers.names.remove(buffers[i]);
    ctx.debug.forget_label(GL_BUFFER, buffers[i]);
  }
}

GLboolean IsBuffer(Context& ctx, GLuint buffer) { return ctx.buffers.names.exists(buffer) ? GL_TRUE : GL_FALSE; }

void BindBuffer(Context& ctx, GLenum target, GLuint buffer) {
  std::shared_ptr<BufferObject>* b = binding(ctx, target);
  if (!b) return;
  if (buffer == 0) b->reset();
  else *b = ctx.buffers.names.get_or_create(buffer);
}

void BufferData(Context& ctx, GLenum target, GLsizeiptr size, const void* data, GLenum usage) {
  std::shared_ptr<BufferObject>* slot = binding(ctx, target);
  if (!slot) return;
  if (size < 0) return ctx.record_error(GL_INVALID_VALUE, "size is negative");
  if (!valid_usage(usage)) return ctx.record_error(GL_INVALID_ENUM, "usage is not a buffer usage");
  BufferObject* b = bound_buffer(ctx, target);
  if (!b) return;
  const auto bytes = static_cast<size_t>(size);
  const auto* from = static_cast<const uint8_t*>(data);
  if (b->data.size() == bytes) {
    // Specified again at the same size (a buffer streamed every frame): the store is reused,
    // without a new allocation whose pages the system would clear and fault in again.
    if (from) std::memmove(b->data.data(), from, bytes);
    else std::fill(b->data.begin(), b->data.end(), uint8_t{0});
  } else {
    // Allocated first: running out of memory leaves the buffer as it was.
    std::vector<uint8_t> store = from ? std::vector<uint8_t>(from, from + bytes) : std::vector<uint8_t>(bytes);
    b->data = std::move(store);
  }
  // A mapped buffer is unmapped by its new contents (as Mesa does).
  b->usage = usage;
  b->unmap();
  b->access = GL_READ_WRITE;
}

void BufferSubData(Context& ctx, GLenum target, GLintptr offset, GLsizeiptr size, const void* data) {
  BufferObject* b = sub_data_buffer(ctx, target, offset, size);
  if (b && data && size > 0) std::memcpy(b->data.data() + offset, data, size_t(size));
}

// GL_ARB_copy_buffer (GL 3.1 2.9.5), its errors checked in Mesa's order: a buffer bound to
// both targets, neither mapped, then the ranges.
void CopyBufferSubData(Context& ctx, GLenum readTarget, GLenum writeTarget, GLintptr readOffset, GLintptr writeOffset,
                       GLsizeiptr size) {
  std::shared_ptr<BufferObject>* read_slot = binding(ctx, readTarget);
  if (!read_slot) return;
  std::shared_ptr<BufferObject>* write_slot = binding(ctx, writeTarget);
  if (!write_slot) return;
  BufferObject* from = read_slot->get();
  BufferObject* to = write_slot->get();
  if (!from || !to) return ctx.record_error(GL_INVALID_OPERATION, "no buffer is bound to readTarget or writeTarget");
  if (from->mapped || to->mapped) return ctx.record_error(GL_INVALID_OPERATION, "the source or destination is mapped");
  if (readOffset < 0 || writeOffset < 0 || size < 0)
    return ctx.record_error(GL_INVALID_VALUE, "readOffset, writeOffset or size is negative");
  const auto count = size_t(size), read_at = size_t(readOffset), write_at = size_t(writeOffset);
  if (read_at > from->data.size() || count > from->data.size() - read_at)
    return ctx.record_error(GL_INVALID_VALUE, "the source range reaches past the read buffer's end");
  if (write_at > to->data.size() || count > to->data.size() - write_at)
    return ctx.record_error(GL_INVALID_VALUE, "the destination range reaches past the write buffer's end");
  if (from == to && read_at < write_at + count && write_at < read_at + count)
    return ctx.record_error(GL_INVALID_VALUE, "the source and destination ranges of one buffer overlap");
  if (count) std::memmove(to->data.data() + write_at, from->data.data() + read_at, count);
}

void GetBufferSubData(Context& ctx, GLenum target, GLintptr offset, GLsizeiptr size, void* data) {
  const BufferObject* b = sub_data_buffer(ctx, target, offset, size);
  if (b && data && size > 0) std::memcpy(data, b->data.data() + offset, size_t(size));
}

void* MapBuffer(Context& ctx, GLenum target, GLenum access) {
  if (!binding(ctx, target)) return nullptr;
  if (access != GL_READ_ONLY && access != GL_WRITE_ONLY && access != GL_READ_WRITE) {
    ctx.record_error(GL_INVALID_ENUM, "access is not GL_READ_ONLY, GL_WRITE_ONLY or GL_READ_WRITE");
    return nullptr;
  }
  BufferObject* b = bound_buffer(ctx, target);
  if (!b) return nullptr;
  if (b->mapped) {
    ctx.record_error(GL_INVALID_OPERATION, "the buffer is already mapped");
    return nullptr;
  }
  b->access = access;
  b->map(0, b->data.size(), access == GL_READ_ONLY    ? GL_MAP_READ_BIT
                            : access == GL_WRITE_ONLY ? GL_MAP_WRITE_BIT
                                                      : GL_MAP_READ_BIT | GL_MAP_WRITE_BIT);
  return b->data.data();
}

// GL 3.0 2.9.3 / GL_ARB_map_buffer_range, with Mesa's INVALID_OPERATION for a zero length
// (GL 4.5, ES 3.0). The store is the client memory that draws read when they are made, so
// nothing waits, and invalidation leaves the contents as they were (they become undefined).
void* MapBufferRange(Context& ctx, GLenum target, GLintptr offset, GLsizeiptr length, GLbitfield access) {
  if (!binding(ctx, target)) return nullptr;
  BufferObject* b = bound_buffer(ctx, target);
  if (!b) return nullptr;
  constexpr GLbitfield kFlags = GL_MAP_READ_BIT | GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_RANGE_BIT |
                                GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_FLUSH_EXPLICIT_BIT | GL_MAP_UNSYNCHRONIZED_BIT;
  const char* problem = nullptr;
  GLenum error = GL_INVALID_VALUE;
  if (offset < 0 || length < 0) problem = "offset or length is negative";
  else if (length == 0) error = GL_INVALID_OPERATION, problem = "length is zero";
  else if (access & ~kFlags) problem = "access has bits that are not GL_MAP_*_BIT flags";
  else if (!(access & (GL_MAP_READ_BIT | GL_MAP_WRITE_BIT)))
    error = GL_INVALID_OPERATION, problem = "access has neither GL_MAP_READ_BIT nor GL_MAP_WRITE_BIT";
  else if ((access & GL_MAP_READ_BIT) &&
           (access & (GL_MAP_INVALIDATE_RANGE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT | GL_MAP_UNSYNCHRONIZED_BIT)))
    error = GL_INVALID_OPERATION, problem = "GL_MAP_READ_BIT with an invalidate or unsynchronized bit";
  else if ((access & GL_MAP_FLUSH_EXPLICIT_BIT) && !(access & GL_MAP_WRITE_BIT))
    error = GL_INVALID_OPERATION, problem = "GL_MAP_FLUSH_EXPLICIT_BIT without GL_MAP_WRITE_BIT";
  else if (size_t(offset) > b->data.size() || size_t(length) > b->data.size() - size_t(offset))
    problem = "offset + length is past the buffer's end";
  else if (b->mapped) error = GL_INVALID_OPERATION, problem = "the buffer is already mapped";
  if (problem) {
    ctx.record_error(error, problem);
    return nullptr;
  }
  const bool read = access & GL_MAP_READ_BIT, write = access & GL_MAP_WRITE_BIT;
  b->access = read && write ? GL_READ_WRITE : read ? GL_READ_ONLY : GL_WRITE_ONLY;
  b->map(size_t(offset), size_t(length), access);
  return b->data.data() + offset;
}

void FlushMappedBufferRange(Context& ctx, GLenum target, GLintptr offset, GLsizeiptr length) {
  if (!binding(ctx, target)) return;
  BufferObject* b = bound_buffer(ctx, target);
  if (!b) return;
  if (offset < 0 || length < 0) return ctx.record_error(GL_INVALID_VALUE, "offset or length is negative");
  if (!b->mapped) return ctx.record_error(GL_INVALID_OPERATION, "the buffer is not mapped");
  if (!(b->access_flags & GL_MAP_FLUSH_EXPLICIT_BIT))
    return ctx.record_error(GL_INVALID_OPERATION, "the buffer is not mapped with GL_MAP_FLUSH_EXPLICIT_BIT");
  if (size_t(offset) > b->map_length || size_t(length) > b->map_length - size_t(offset))
    return ctx.record_error(GL_INVALID_VALUE, "offset + length is past the mapped range");
  // Writes through the mapping are in the store already.
}

GLboolean UnmapBuffer(Context& ctx, GLenum target) {
  BufferObject* b = bound_buffer(ctx, target);
  if (!b) return GL_FALSE;
  if (!b->mapped) {
    ctx.record_error(GL_INVALID_OPERATION, "the buffer is not mapped");
    return GL_FALSE;
  }
  b->unmap();
  return GL_TRUE;  // the store is never corrupted while mapped
}

void GetBufferParameteriv(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  if (!binding(ctx, target)) return;
  // The mapped range's state: GL 3.0's, which Mesa offers with ARB_map_buffer_range (ES's
  // EXT_map_buffer_range has no such queries).
  const bool range = !ctx.es1() && !ctx.es2() &&
                     (pname == GL_BUFFER_ACCESS_FLAGS || pname == GL_BUFFER_MAP_OFFSET || pname == GL_BUFFER_MAP_LENGTH);
  if (pname != GL_BUFFER_SIZE && pname != GL_BUFFER_USAGE && pname != GL_BUFFER_ACCESS && pname != GL_BUFFER_MAPPED &&
      !range)
    return ctx.record_error(GL_INVALID_ENUM, "pname is not a buffer parameter");
  const BufferObject* b = bound_buffer(ctx, target);
  if (!b || !params) return;
  auto clamped = [](size_t v) { return GLint(std::min<size_t>(v, 0x7fffffff)); };
  switch (pname) {
    case GL_BUFFER_SIZE: *params = clamped(b->data.size()); break;
    case GL_BUFFER_USAGE: *params = GLint(b->usage); break;
    case GL_BUFFER_ACCESS: *params = GLint(b->access); break;
    case GL_BUFFER_ACCESS_FLAGS: *params = GLint(b->access_flags); break;
    case GL_BUFFER_MAP_OFFSET: *params = clamped(b->map_offset); break;
    case GL_BUFFER_MAP_LENGTH: *params = clamped(b->map_length); break;
    default: *params = b->mapped ? GL_TRUE : GL_FALSE; break;
  }
}

void GetBufferPointerv(Context& ctx, GLenum target, GLenum pname, void** params) {
  if (!binding(ctx, target)) return;
  if (pname != GL_BUFFER_MAP_POINTER) return ctx.record_error(GL_INVALID_ENUM, "pname is not GL_BUFFER_MAP_POINTER");
  BufferObject* b = bound_buffer(ctx, target);
  if (!b || !params) return;
  *params = b->mapped ? b->data.data() + b->map_offset : nullptr;
}

// The ARB_vertex_buffer_object names.
void GenBuffersARB(Context& ctx, GLsizei n, GLuint* buffers) { GenBuffers(ctx, n, buffers); }
void DeleteBuffersARB(Context& ctx, GLsizei n, const GLuint* buffers) { DeleteBuffers(ctx, n, buffers); }
GLboolean IsBufferARB(Context& ctx, GLuint buffer) { return IsBuffer(ctx, buffer); }
void BindBufferARB(Context& ctx, GLenum target, GLuint buffer) { BindBuffer(ctx, target, buffer); }
void BufferDataARB(Context& ctx, GLenum target, GLsizeiptrARB size, const void* data, GLenum usage) {
  BufferData(ctx, target, size, data, usage);
}
void BufferSubDataARB(Context& ctx, GLenum target, GLintptrARB offset, GLsizeiptrARB size, const void* data) {
  BufferSubData(ctx, target, offset, size, data);
}
void GetBufferSubDataARB(Context& ctx, GLenum target, GLintptrARB offset, GLsizeiptrARB size, void* data) {
  GetBufferSubData(ctx, target, offset, size, data);
}
void* MapBufferARB(Context& ctx, GLenum target, GLenum access) { return MapBuffer(ctx, target, access); }
GLboolean UnmapBufferARB(Context& ctx, GLenum target) { return UnmapBuffer(ctx, target); }
void GetBufferParameterivARB(Context& ctx, GLenum target, GLenum pname, GLint* params) {
  GetBufferParameteriv(ctx, target, pname, params);
}
void GetBufferPointervARB(Context& ctx, GLenum target, GLenum pname, void** params) {
  GetBufferPointerv(ctx, target, pname, params);
}

}  // namespace pineda::gl
