// Table entries shared by every kind of GL object: glGen* of up to N names, glDelete* of two
// names (existing, deleted or never made). The call is a template argument, so that the core,
// ARB and EXT names of a call share the entry.
#pragma once
#include <GL/gl.h>

#include "tests/fuzz/gl_calls.h"

namespace pineda::fuzz {

template <auto Gen, GLsizei N>
void gen_names(FuzzInput& in, ClientMemory&) {
  GLuint names[N];
  Gen(in.bounded_size(N), names);
}

template <auto Delete>
void delete_names(FuzzInput& in, ClientMemory&) {
  const GLuint names[2] = {in.name(), in.name()};
  Delete(in.bounded_size(2), names);
}

}  // namespace pineda::fuzz
