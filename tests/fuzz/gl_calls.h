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

// Every fuzzed call, each exported GL entry point through its own name at least once:
// GL 1.x fixed function (gl_calls.cpp), then GL 2.1's shaders and programs with their ARB
// names (gl2_program_calls.cpp), uniforms and generic vertex attributes (gl2_uniform_calls.cpp),
// framebuffer objects with the other GL 2.x state and their EXT names (gl2_framebuffer_calls.cpp),
// integer queries of GL 1.x float state (gl1_query_calls.cpp), the calls whose arguments are
// only numbers, in every type and vector form (gl_variant_calls.cpp, typed_call.h), OpenGL ES
// 1.1's fixed-point and OES calls (es1_fixed_calls.cpp), the other queries (gl_get_calls.cpp),
// compressed, 1D and 3D texture images (gl_texture_image_calls.cpp), the other forms of the
// GL 1.x state calls (gl1_parameter_calls.cpp), debug output (gl_debug_calls.cpp), robustness
// (gl_robust_calls.cpp), EXT_vertex_array (gl_vertex_array_ext_calls.cpp) and EGL
// (egl_calls.cpp).
std::span<const GlCall> gl_calls();
std::span<const GlCall> program_calls();
std::span<const GlCall> uniform_calls();
std::span<const GlCall> framebuffer_calls();
std::span<const GlCall> query_calls();
std::span<const GlCall> variant_calls();
std::span<const GlCall> es1_calls();
std::span<const GlCall> get_calls();
std::span<const GlCall> texture_image_calls();
std::span<const GlCall> parameter_calls();
std::span<const GlCall> debug_calls();
std::span<const GlCall> robustness_calls();
std::span<const GlCall> vertex_array_ext_calls();

// EGL's calls (egl_calls.cpp), named egl*, on the EGL objects of one input's session. An EGL
// call runs through run_egl_call: when it leaves no EGL context current where one was, the
// session's `restore_context` makes the fuzzer's own context current again. Ending the session
// releases and terminates every display the input got.
std::span<const GlCall> egl_calls();
void begin_egl_session(void (*restore_context)());
void run_egl_call(const GlCall& call, FuzzInput& in, ClientMemory& memory);
void end_egl_session();

}  // namespace pineda::fuzz
