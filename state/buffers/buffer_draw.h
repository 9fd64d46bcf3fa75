// What a draw from vertex arrays checks when the arrays or indices live in buffer objects.
#pragma once
#include <cstddef>

namespace pineda {

class Context;

// False when the draw must not run: a buffer it reads is mapped (GL_INVALID_OPERATION
// recorded), or an enabled buffer-backed array does not hold vertex `last_index` (dropped
// without error, as Mesa does, so that nothing is read out of bounds).
bool arrays_ready(Context& ctx, size_t last_index);

// The `bytes` bytes of index data glDrawElements reads: client memory, or `indices` taken as
// an offset into the bound element array buffer. Null when the draw must not run (the
// buffer is mapped: GL_INVALID_OPERATION recorded; or the range is outside its store).
const void* element_indices(Context& ctx, const void* indices, size_t bytes);

}  // namespace pineda
