// The API versions Pineda implements: contexts asking for more fail. Raising a constant
// here is all the driver needs to offer a new version.
#pragma once

namespace pineda::driver {

inline constexpr int kMaxGLMajor = 2;
inline constexpr int kMaxGLMinor = 1;
// OpenGL ES 1.1 (the common profile) through EGL: EGL_OPENGL_ES_API, EGL_OPENGL_ES_BIT.
inline constexpr bool kHasGLES1 = true;
// OpenGL ES 2.0 through EGL: CONTEXT_CLIENT_VERSION 2, EGL_OPENGL_ES2_BIT.
inline constexpr int kMaxGLESMajor = 2;

inline constexpr bool kHasGLES2 = kMaxGLESMajor >= 2;
inline constexpr bool kHasGLES = kHasGLES1 || kHasGLES2;

// A version GL defines (1.0-1.5, 2.0-2.1, 3.0-3.3, 4.0-4.6).
constexpr bool is_gl_version(int major, int minor) {
  constexpr int kLastMinor[] = {-1, 5, 1, 3, 6};
  return major >= 1 && major <= 4 && minor >= 0 && minor <= kLastMinor[major];
}

constexpr bool gl_version_supported(int major, int minor) {
  return is_gl_version(major, minor) &&
         (major < kMaxGLMajor || (major == kMaxGLMajor && minor <= kMaxGLMinor));
}

// ES 1.0 and 1.1 (a 1.0 request gets 1.1, which is backward compatible) and, later, ES 2.0.
constexpr bool gles_version_supported(int major, int minor) {
  if (major == 1) return kHasGLES1 && (minor == 0 || minor == 1);
  return major == 2 && minor == 0 && kHasGLES2;
}

}  // namespace pineda::driver
