// libFuzzer target: the input bytes choose a sequence of GL calls from the tables in
// gl_calls.cpp (GL 1.x) and gl2_*_calls.cpp (shaders, programs, uniforms, generic attributes,
// framebuffer objects, pixel buffers) and their arguments, run on a fresh 32x32 OSMesa context
// per input so that every crash reproduces from its input alone. PINEDA_FUZZ_TRACE=1 prints
// each call's name as it is made.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "tests/fuzz/client_memory.h"
#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/gl_calls.h"

namespace {

constexpr int kSize = 32;
constexpr int kMaxCallsPerInput = 256;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("PINEDA_THREADS", "1", 1);  // one rasterizer thread: the same run for every input
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace pineda::fuzz;
  static const bool trace = getenv("PINEDA_FUZZ_TRACE") != nullptr;  // each call's name, to read a finding
  OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);
  if (!context) abort();
  std::vector<uint8_t> framebuffer(kSize * kSize * 4);
  if (!OSMesaMakeCurrent(context, framebuffer.data(), GL_UNSIGNED_BYTE, kSize, kSize)) abort();
  {
    ClientMemory memory;
    FuzzInput in(data, size);
    const auto calls = gl_calls();
    for (int n = 0; n < kMaxCallsPerInput && !in.empty(); ++n) {
      const GlCall& call = calls[in.byte() % calls.size()];
      if (trace) fprintf(stderr, "%s\n", call.name);
      call.run(in, memory);
    }
    glFinish();
    // The context goes before the memory its arrays and feedback buffer point into.
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context);
  }
  return 0;
}
