// libFuzzer target: the input bytes choose a sequence of GL and EGL calls from the tables
// listed in gl_calls.h and their arguments, run on a fresh 32x32 OSMesa context per input (or
// on an EGL context that an EGL call made current) so that every crash reproduces from its
// input alone. PINEDA_FUZZ_TRACE=1 prints each call's name as it is made.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "tests/fuzz/client_memory.h"
#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/gl_calls.h"

namespace {

constexpr int kSize = 32;
constexpr int kMaxCallsPerInput = 256;

OSMesaContext context = nullptr;
std::vector<uint8_t> framebuffer(kSize * kSize * 4);

void make_context_current() {
  if (!OSMesaMakeCurrent(context, framebuffer.data(), GL_UNSIGNED_BYTE, kSize, kSize)) abort();
}

bool is_egl_call(const pineda::fuzz::GlCall& call) { return std::strncmp(call.name, "egl", 3) == 0; }

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  setenv("PINEDA_THREADS", "1", 1);  // one rasterizer thread: the same run for every input
  // EGL's default display is the surfaceless one, and X11 displays find no server.
  unsetenv("EGL_PLATFORM");
  unsetenv("DISPLAY");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace pineda::fuzz;
  static const bool trace = getenv("PINEDA_FUZZ_TRACE") != nullptr;  // each call's name, to read a finding
  context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, nullptr);
  if (!context) abort();
  std::fill(framebuffer.begin(), framebuffer.end(), 0);
  make_context_current();
  begin_egl_session(make_context_current);
  {
    ClientMemory memory;
    FuzzInput in(data, size);
    const auto calls = gl_calls();
    for (int n = 0; n < kMaxCallsPerInput && !in.empty(); ++n) {
      const GlCall& call = calls[in.index(calls.size())];
      if (trace) fprintf(stderr, "%s\n", call.name);
      if (is_egl_call(call)) run_egl_call(call, in, memory);
      else call.run(in, memory);
    }
    glFinish();
    // The contexts go before the memory their arrays and feedback buffers point into.
    end_egl_session();
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context);
  }
  return 0;
}
