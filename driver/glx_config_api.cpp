// Configs and visuals: glXGetFBConfigs, glXChooseFBConfig, glXGetFBConfigAttrib,
// glXGetVisualFromFBConfig, glXChooseVisual, glXGetConfig.
#include "driver/glx_config.h"

#include <X11/Xutil.h>

#include <cstdlib>

#include "driver/glx_error.h"
#include "driver/glx_registry.h"

namespace pineda::glx {
namespace {

// The caller frees it with XFree, which is free().
GLXFBConfig* to_xfree_array(const std::vector<const Config*>& configs, int* count) {
  *count = static_cast<int>(configs.size());
  if (configs.empty()) return nullptr;
  auto* array = static_cast<GLXFBConfig*>(std::malloc(configs.size() * sizeof(GLXFBConfig)));
  if (!array) {
    *count = 0;
    return nullptr;
  }
  for (size_t i = 0; i < configs.size(); ++i) array[i] = handle_of(configs[i]);
  return array;
}

XVisualInfo* visual_info(Display* dpy, const Config& c) {
  XVisualInfo tmpl{};
  tmpl.visualid = c.visual_id;
  tmpl.screen = c.screen;
  int count = 0;
  return XGetVisualInfo(dpy, VisualIDMask | VisualScreenMask, &tmpl, &count);
}

bool valid_screen(Display* dpy, int screen) { return screen >= 0 && screen < ScreenCount(dpy); }

}  // namespace
}  // namespace pineda::glx

using namespace pineda::glx;

PINEDA_GLX_EXPORT GLXFBConfig* glXGetFBConfigs(Display* dpy, int screen, int* nelements) {
  int ignored;
  if (!nelements) nelements = &ignored;
  *nelements = 0;
  if (!dpy || !valid_screen(dpy, screen)) return nullptr;
  auto lock = Registry::instance().lock();
  DisplayState* d = Registry::instance().get(dpy);
  std::vector<const Config*> configs;
  for (const auto& c : d->configs)
    if (c->screen == screen) configs.push_back(c.get());
  return to_xfree_array(configs, nelements);
}

PINEDA_GLX_EXPORT GLXFBConfig* glXChooseFBConfig(Display* dpy, int screen, const int* attribs,
                                                 int* nitems) {
  int ignored;
  if (!nitems) nitems = &ignored;
  *nitems = 0;
  if (!dpy || !valid_screen(dpy, screen)) return nullptr;
  std::vector<const Config*> configs;
  bool known;
  {
    auto lock = Registry::instance().lock();
    known = choose_fbconfigs(*Registry::instance().get(dpy), screen, attribs, &configs);
  }
  if (!known) {
    send_x_error(dpy, BadValue, GlxRequest::GetFBConfigs);
    return nullptr;
  }
  return to_xfree_array(configs, nitems);
}

PINEDA_GLX_EXPORT int glXGetFBConfigAttrib(Display* dpy, GLXFBConfig fbconfig, int attribute,
                                           int* value) {
  auto lock = Registry::instance().lock();
  DisplayState* d = Registry::instance().get(dpy);
  const Config* c = d ? d->find_config(fbconfig) : nullptr;
  if (!c) return GLX_BAD_VISUAL;  // the spec's answer for an invalid config
  if (!value) return GLX_BAD_VALUE;
  return config_attribute(*c, attribute, value);
}

PINEDA_GLX_EXPORT XVisualInfo* glXGetVisualFromFBConfig(Display* dpy, GLXFBConfig fbconfig) {
  const Config* c;
  {
    auto lock = Registry::instance().lock();
    DisplayState* d = Registry::instance().get(dpy);
    c = d ? d->find_config(fbconfig) : nullptr;
  }
  return c ? visual_info(dpy, *c) : nullptr;
}

PINEDA_GLX_EXPORT XVisualInfo* glXChooseVisual(Display* dpy, int screen, int* attribs) {
  if (!dpy || !valid_screen(dpy, screen)) return nullptr;
  const Config* c;
  {
    auto lock = Registry::instance().lock();
    c = choose_visual_config(*Registry::instance().get(dpy), screen, attribs);
  }
  return c ? visual_info(dpy, *c) : nullptr;
}

PINEDA_GLX_EXPORT int glXGetConfig(Display* dpy, XVisualInfo* vis, int attribute, int* value) {
  if (!dpy) return GLX_NO_EXTENSION;
  if (!vis || !value) return GLX_BAD_VALUE;
  if (!valid_screen(dpy, vis->screen)) return GLX_BAD_SCREEN;
  auto lock = Registry::instance().lock();
  const Config* c = config_of_visual(*Registry::instance().get(dpy), vis->visualid);
  if (!c) {
    if (attribute == GLX_USE_GL) {
      *value = False;
      return Success;
    }
    return GLX_BAD_VISUAL;
  }
  // glXGetConfig answers only the GLX 1.2 visual attributes.
  switch (attribute) {
    case GLX_USE_GL: case GLX_BUFFER_SIZE: case GLX_LEVEL: case GLX_RGBA: case GLX_DOUBLEBUFFER:
    case GLX_STEREO: case GLX_AUX_BUFFERS: case GLX_RED_SIZE: case GLX_GREEN_SIZE:
    case GLX_BLUE_SIZE: case GLX_ALPHA_SIZE: case GLX_DEPTH_SIZE: case GLX_STENCIL_SIZE:
    case GLX_ACCUM_RED_SIZE: case GLX_ACCUM_GREEN_SIZE: case GLX_ACCUM_BLUE_SIZE:
    case GLX_ACCUM_ALPHA_SIZE: case GLX_SAMPLE_BUFFERS: case GLX_SAMPLES: case GLX_FBCONFIG_ID:
    case GLX_X_VISUAL_TYPE: case GLX_CONFIG_CAVEAT: case GLX_TRANSPARENT_TYPE:
    case GLX_VISUAL_ID:
      return config_attribute(*c, attribute, value);
    default: return GLX_BAD_ATTRIBUTE;
  }
}
