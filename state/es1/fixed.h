// GLfixed, the 16.16 two's-complement numbers of OpenGL ES 1.1 (OES_fixed_point), to and from
// float the way Mesa converts them.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <climits>
#include <cmath>

namespace pineda::es1 {

inline float from_fixed(GLfixed x) { return static_cast<float>(x) / 65536.f; }

// Truncates toward zero; saturates outside the range; NaN is 0 (converting it is undefined).
inline GLfixed to_fixed(double v) {
  if (std::isnan(v)) return 0;
  const double scaled = v * 65536.0;
  if (scaled >= double(INT_MAX)) return INT_MAX;
  if (scaled <= double(INT_MIN)) return INT_MIN;
  return static_cast<GLfixed>(scaled);
}

// An integer state value as GLfixed: outside the 16-bit range it saturates (Mesa's INT_TO_FIXED).
inline GLfixed int_to_fixed(long long v) {
  if (v > SHRT_MAX) return INT_MAX;
  if (v < SHRT_MIN) return INT_MIN;
  return static_cast<GLfixed>(v * 65536);
}

}  // namespace pineda::es1
