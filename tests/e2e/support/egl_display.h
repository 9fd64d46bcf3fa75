// The surfaceless EGL display the test surfaces use.
#pragma once

namespace pineda::test {

// Initialized once per process (EGL_NO_DISPLAY if it cannot be); an EGLDisplay, without the
// EGL header and the X11 names it brings.
void* egl_display();

}  // namespace pineda::test
