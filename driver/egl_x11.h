// EGL's X11 platform (EGL_KHR_platform_x11, EGL_EXT_platform_x11): displays on an Xlib
// Display*, configs with the X server's TrueColor visual, and window and pixmap surfaces
// whose buffers and presentation are GLX's (glx_drawable.h).
#pragma once
#include "driver/egl_objects.h"

namespace pineda::egl {

// eglInitialize of an X11 display: opens the default X display when the application gave
// none, and makes the configs once. false when there is no X server to talk to.
bool initialize_x11(Display& display);

// eglSwapBuffers of a window or pixmap surface current to the calling thread, whose GL
// context is `gl`: presents the back buffer, then follows the window's size. Returns the
// EGL error (EGL_BAD_NATIVE_WINDOW once the window is gone) or EGL_SUCCESS.
EGLint swap_native(Surface& s, pineda::Context& gl);

// Before a window surface is made current: its buffers follow the window's size. false
// when the window no longer exists. Caller holds the registry lock.
bool follow_native_size(Surface& s);

// glFlush, glFinish, eglWaitClient: what was rendered into the front buffer of a window or
// pixmap surface (a single-buffered one's only buffer) reaches the X server.
void show_front(Surface& s);

// The EGL_RENDER_BUFFER of a surface.
EGLint render_buffer(const Surface& s);

}  // namespace pineda::egl
