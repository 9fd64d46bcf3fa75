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

std::span<const GlCall> gl_calls();

}  // namespace pineda::fuzz
