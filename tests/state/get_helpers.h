// Small wrappers that read one piece of state through each glGet* type.
#pragma once
#include <GL/gl.h>

#include <vector>

namespace pineda::test {

inline std::vector<GLint> get_ints(GLenum pname, int n) {
  std::vector<GLint> v(n, -7777);
  glGetIntegerv(pname, v.data());
  return v;
}
inline std::vector<GLfloat> get_floats(GLenum pname, int n) {
  std::vector<GLfloat> v(n, -7777.f);
  glGetFloatv(pname, v.data());
  return v;
}
inline std::vector<GLdouble> get_doubles(GLenum pname, int n) {
  std::vector<GLdouble> v(n, -7777.0);
  glGetDoublev(pname, v.data());
  return v;
}
inline std::vector<GLboolean> get_bools(GLenum pname, int n) {
  std::vector<GLboolean> v(n, 77);
  glGetBooleanv(pname, v.data());
  return v;
}
inline GLint get_int(GLenum pname) { return get_ints(pname, 1)[0]; }
inline GLfloat get_float(GLenum pname) { return get_floats(pname, 1)[0]; }
inline GLboolean get_bool(GLenum pname) { return get_bools(pname, 1)[0]; }
inline GLdouble get_double(GLenum pname) { return get_doubles(pname, 1)[0]; }

// GL 1.1 spec 6.1.2: a colour component c becomes an integer by a linear map of [-1, 1]
// onto [-2^31, 2^31 - 1]; implementations differ by one in the rounding.
constexpr double kIntColorScale = 2147483647.0;

}  // namespace pineda::test
