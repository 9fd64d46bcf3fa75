// The SSE floating-point modes (MXCSR: rounding, flush to zero, denormals are zero) of the
// running thread, set for a scope.
#pragma once
#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#define PINEDA_HAS_MXCSR 1
#endif

namespace pineda::raster {

// Round to nearest, no flush to zero, every exception masked: what a thread starts with.
constexpr unsigned kDefaultFloatModes = 0x1F80;
// Flush to zero and denormals are zero: where shaders run (shader::ir::FlushDenormals).
constexpr unsigned kFlushDenormalModes = 0x8040;
constexpr unsigned kShaderFloatModes = kDefaultFloatModes | kFlushDenormalModes;

class ScopedFloatModes {
 public:
#ifdef PINEDA_HAS_MXCSR
  explicit ScopedFloatModes(unsigned modes) : own_(_mm_getcsr()) { _mm_setcsr(modes); }
  ~ScopedFloatModes() { _mm_setcsr(own_); }
  void set(unsigned modes) { _mm_setcsr(modes); }
  static unsigned current() { return _mm_getcsr(); }

 private:
  unsigned own_;
#else
  explicit ScopedFloatModes(unsigned) {}
  void set(unsigned) {}
  static unsigned current() { return kDefaultFloatModes; }
#endif
  ScopedFloatModes(const ScopedFloatModes&) = delete;
  ScopedFloatModes& operator=(const ScopedFloatModes&) = delete;
};

}  // namespace pineda::raster
