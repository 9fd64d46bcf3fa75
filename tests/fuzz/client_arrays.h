// Vertex array pointers the fuzzed calls hand GL: offsets into the bound array buffer, or
// pointers into ClientMemory from which vertices 0 to kMaxVertexIndex can be read.
#pragma once
#include <GL/gl.h>

#include "tests/fuzz/client_memory.h"
#include "tests/fuzz/fuzz_input.h"

namespace pineda::fuzz {

// A client array pointer: an offset into the bound buffer object (any value: GL checks it) or
// a pointer into `arrays` from which vertices 0 to kMaxVertexIndex can be read.
const void* array_pointer(FuzzInput& in, const ClientMemory& memory);

// A stride for client arrays: up to kArrayStrideMax, sometimes negative (rejected).
GLsizei array_stride(FuzzInput& in);

// Whether a client array (fixed-function or generic attribute) takes its data from buffer
// `name`. Deleting that buffer resets the array's binding to 0 (GL 1.5 2.9), and the array's
// offset then reads as a client pointer: an application error the fuzzer must not make.
bool array_uses_buffer(GLuint name);

}  // namespace pineda::fuzz
