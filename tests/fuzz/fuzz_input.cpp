#include "tests/fuzz/fuzz_input.h"

#include <climits>
#include <cmath>
#include <limits>

namespace pineda::fuzz {
namespace {

// Enums of no GL call here, and neighbours of common ones.
constexpr GLenum kInvalidEnums[] = {0, 1, 0x0BAD, 0x1234, 0x8000, 0xFFFF, 0xFFFFFFFFu, GL_FLOAT + 1, GL_POLYGON + 1};

constexpr GLint kExtremeInts[] = {INT_MIN, INT_MIN + 1, -65536, -1, INT_MAX, INT_MAX - 1, 1 << 20, 8193, 65536};

}  // namespace

GLenum FuzzInput::enumeration(std::span<const GLenum> valid) {
  const uint8_t pick = byte();
  if (pick % 8 != 7 && !valid.empty()) return valid[(pick / 8) % valid.size()];
  return kInvalidEnums[(pick / 8) % std::size(kInvalidEnums)];
}

GLint FuzzInput::integer(GLint lo, GLint hi) {
  const uint8_t pick = byte();
  if (pick % 8 == 7) return kExtremeInts[(pick / 8) % std::size(kExtremeInts)];
  return in_.ConsumeIntegralInRange<GLint>(lo, hi);
}

GLsizei FuzzInput::bounded_size(GLsizei limit) {
  const uint8_t pick = byte();
  if (pick % 16 == 15) return pick & 0x80 ? -1 : INT_MIN;
  return in_.ConsumeIntegralInRange<GLsizei>(0, limit);
}

CheckedSize FuzzInput::checked_size(GLsizei limit) {
  const uint8_t pick = byte();
  if (pick % 8 != 7) return {in_.ConsumeIntegralInRange<GLsizei>(0, limit), false};
  // 8195: beyond the largest texture width with borders (8192 + 2), which 8193 was not.
  constexpr GLsizei kBeyondLimits[] = {-1, INT_MIN, 8195, 1 << 20, 1185050933, INT_MAX};
  return {kBeyondLimits[(pick / 8) % std::size(kBeyondLimits)], true};
}

GLfloat FuzzInput::real() {
  const uint8_t pick = byte();
  switch (pick % 16) {
    case 12: return std::numeric_limits<float>::quiet_NaN();
    case 13: return (pick & 0x80 ? -1 : 1) * std::numeric_limits<float>::infinity();
    case 14: return (pick & 0x80 ? -1e30f : 1e30f);
    case 15: return (pick & 0x80 ? 3.4e38f : 1e-40f);
    default: return in_.ConsumeFloatingPointInRange<float>(-4.f, 4.f);
  }
}

GLfloat FuzzInput::unit() {
  const uint8_t pick = byte();
  if (pick % 16 == 15) return real();
  return in_.ConsumeProbability<float>();
}

GLuint FuzzInput::name() {
  const uint8_t pick = byte();
  if (pick % 16 == 15) return pick & 0x80 ? 0xFFFFFFFFu : 100000u;
  return pick % 9;
}

}  // namespace pineda::fuzz
