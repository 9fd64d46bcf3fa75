// The highest desktop GL version Pineda implements: contexts asking for more fail.
#pragma once

namespace pineda::driver {

inline constexpr int kMaxGLMajor = 1;
inline constexpr int kMaxGLMinor = 1;

// A version GL defines (1.0-1.5, 2.0-2.1, 3.0-3.3, 4.0-4.6).
constexpr bool is_gl_version(int major, int minor) {
  constexpr int kLastMinor[] = {-1, 5, 1, 3, 6};
  return major >= 1 && major <= 4 && minor >= 0 && minor <= kLastMinor[major];
}

constexpr bool gl_version_supported(int major, int minor) {
  return is_gl_version(major, minor) &&
         (major < kMaxGLMajor || (major == kMaxGLMajor && minor <= kMaxGLMinor));
}

}  // namespace pineda::driver
