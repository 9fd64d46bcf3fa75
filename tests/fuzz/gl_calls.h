// The table of fuzzed GL calls: each draws its arguments by kind and makes the call.
#pragma once
#include <span>

#include "tests/fuzz/client_memory.h"
#include "tests/fuzz/fuzz_input.h"

namespace pineda::fuzz {

struct GlCall {
  const char* name;
  void (*run)(FuzzInput& in, ClientMemory& memory);
};

// Every fuzzed call: GL 1.x fixed function (gl_calls.cpp), then GL 2.1's shaders and programs
// (gl2_program_calls.cpp), uniforms and generic vertex attributes (gl2_uniform_calls.cpp), and
// framebuffer objects with the other GL 2.x state (gl2_framebuffer_calls.cpp), and integer
// queries of GL 1.x float state (gl1_query_calls.cpp).
std::span<const GlCall> gl_calls();
std::span<const GlCall> program_calls();
std::span<const GlCall> uniform_calls();
std::span<const GlCall> framebuffer_calls();
std::span<const GlCall> query_calls();

}  // namespace pineda::fuzz
