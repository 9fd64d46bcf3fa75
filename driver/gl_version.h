// The API versions Pineda implements: contexts asking for more fail. Raising a constant
// here is all the driver needs to offer a new version.
#pragma once

namespace pineda::driver {

inline constexpr int kMaxGLMajor = 1;
inline constexpr int kMaxGLMinor = 5;
// 0: no OpenGL ES yet. 2 offers ES 2.0 through EGL (EGL_OPENGL_ES_API, EGL_OPENGL_ES2_BIT).
inline constexpr int kMaxGLESMajor = 0;

inline constexpr bool kHasGLES2 = kMaxGLESMajor >= 2;

// A version GL defines (1.0-1.5, 2.0-2.1, 3.0-3.3, 4.0-4.6).
constexpr bool is_gl_version(int major, int minor) {
  constexpr int kLastMinor[] = {-1, 5, 1, 3, 6};
  return major >= 1 && major <= 4 && minor >= 0 && minor <= kLastMinor[major];
}

constexpr bool gl_version_supported(int major, int minor) {
  return is_gl_version(major, minor) &&
         (major < kMaxGLMajor || (major == kMaxGLMajor && minor <= kMaxGLMinor));
}

// Only ES 2.0 is planned (no ES 1.x; ES 3 once the constant grows).
constexpr bool gles_version_supported(int major, int minor) {
  return major == 2 && minor == 0 && kHasGLES2;
}

}  // namespace pineda::driver
