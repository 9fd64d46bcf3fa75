// The X11 platform's displays: opening the default X display, and the configs, which are the
// surfaceless platform's with EGL_WINDOW_BIT and EGL_PIXMAP_BIT on the screen's TrueColor
// visual in X's 32-bit pixel layout (what GLX presents to, glx_config.cpp).
#include "driver/glx_objects.h"  // first: X11 headers

#include "driver/egl_config.h"
#include "driver/egl_x11.h"
#include "driver/glx_config.h"

namespace pineda::egl {

bool initialize_x11(Display& display) {
  if (!display.x11) {
    ::Display* dpy = display.native ? static_cast<::Display*>(display.native) : XOpenDisplay(nullptr);
    if (!dpy) return false;
    display.x11 = dpy;
    if (display.screen < 0 || display.screen >= ScreenCount(dpy)) display.screen = DefaultScreen(dpy);
  }
  if (!display.configs.empty()) return true;
  display.configs = surfaceless_configs();
  const std::vector<XVisualInfo> visuals =
      glx::usable_visuals(static_cast<::Display*>(display.x11), display.screen, 24);
  if (visuals.empty()) return true;  // pbuffers only
  const VisualID visual = visuals.front().visualid;
  for (Config& c : display.configs) {
    // Multisampled: double-buffered windows only (glx_drawable.cpp), no pixmaps.
    c.surface_type |= c.samples ? EGL_WINDOW_BIT : EGL_WINDOW_BIT | EGL_PIXMAP_BIT;
    c.native_visual_id = static_cast<EGLint>(visual);
    c.native_visual_type = TrueColor;
  }
  return true;
}

}  // namespace pineda::egl
