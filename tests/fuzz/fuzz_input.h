// The arguments of the fuzzed GL calls, drawn from the input bytes by kind: mostly values the
// call accepts, sometimes the values that must be rejected (invalid enums, negative and huge
// sizes, NaN, infinities, 1e30, names of no object).
#pragma once
#include <GL/gl.h>
#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <initializer_list>
#include <span>

namespace pineda::fuzz {

// A size drawn for a call whose limits decide: `huge` is set when it lies beyond every limit
// (negative or above every maximum texture size), so the call must reject it without reading.
struct CheckedSize {
  GLsizei value;
  bool huge;
};

class FuzzInput {
 public:
  FuzzInput(const uint8_t* data, size_t size) : in_(data, size) {}

  bool empty() { return in_.remaining_bytes() == 0; }
  uint8_t byte() { return in_.ConsumeIntegral<uint8_t>(); }
  // An index into a table of `size` entries (one byte, or two once the table has more than 256).
  size_t index(size_t size) { return in_.ConsumeIntegralInRange<size_t>(0, size - 1); }
  bool boolean() { return in_.ConsumeBool(); }

  // One of `valid` (7 times in 8), otherwise an enum the call does not take.
  GLenum enumeration(std::span<const GLenum> valid);
  GLenum enumeration(std::initializer_list<GLenum> valid) { return enumeration({valid.begin(), valid.size()}); }
  // An integer in [lo, hi] (7 times in 8), otherwise an extreme (INT_MIN, -1, INT_MAX, ...).
  GLint integer(GLint lo, GLint hi);
  // An offset into client memory: always in [0, max].
  size_t offset(size_t max) { return in_.ConsumeIntegralInRange<size_t>(0, max); }
  // A size the call reads or writes client memory for: [0, limit], sometimes negative.
  GLsizei bounded_size(GLsizei limit);
  // A size the call checks against its limits: [0, limit] or one beyond every limit.
  CheckedSize checked_size(GLsizei limit);
  // A coordinate or parameter: mostly in [-4, 4], sometimes NaN, infinite, 1e30 or tiny.
  GLfloat real();
  GLdouble real_d() { return real(); }
  // A colour or weight, mostly in [0, 1].
  GLfloat unit();
  // An object name: mostly 0 to 8 (some exist, some were deleted), sometimes one never made.
  GLuint name();

 private:
  FuzzedDataProvider in_;
};

}  // namespace pineda::fuzz
