// GL's conversion of integer colour and normal components to floating point
// (GL 1.5 table 2.9): unsigned types map onto [0, 1], signed ones onto [-1, 1].
#pragma once
#include <GL/gl.h>

namespace pineda {

inline float norm(GLubyte v) { return v / 255.f; }
inline float norm(GLbyte v) { return (2.f * v + 1.f) / 255.f; }
inline float norm(GLushort v) { return v / 65535.f; }
inline float norm(GLshort v) { return (2.f * v + 1.f) / 65535.f; }
inline float norm(GLuint v) { return static_cast<float>(v / 4294967295.0); }
inline float norm(GLint v) { return static_cast<float>((2.0 * v + 1.0) / 4294967295.0); }
inline float norm(GLfloat v) { return v; }
inline float norm(GLdouble v) { return static_cast<float>(v); }

}  // namespace pineda
