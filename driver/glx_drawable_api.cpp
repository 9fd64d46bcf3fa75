// GLX drawables: glXCreateWindow, glXCreatePixmap, glXCreateGLXPixmap, glXCreatePbuffer,
// their destruction, glXQueryDrawable, glXSelectEvent and glXGetSelectedEvent.
#include "driver/glx_objects.h"

#include <algorithm>
#include <optional>

#include "driver/glx_config.h"
#include "driver/glx_drawable.h"
#include "driver/glx_error.h"
#include "driver/glx_registry.h"

namespace pineda::glx {
namespace {

struct Failure {
  unsigned char code;
  bool glx;
  XID resource = 0;
};

void report(Display* dpy, const Failure& f, GlxRequest minor_opcode) {
  if (f.glx)
    send_glx_error(dpy, static_cast<GlxError>(f.code), minor_opcode, f.resource);
  else
    send_x_error(dpy, f.code, minor_opcode, f.resource);
}

Failure glx_failure(GlxError code, XID resource = 0) {
  return {static_cast<unsigned char>(code), true, resource};
}

// Runs `body` with the registry locked, then reports its failure, if any, unlocked.
template <class Body>
XID with_display(Display* dpy, GlxRequest minor_opcode, Body body) {
  std::optional<Failure> failure;
  XID result = None;
  {
    auto lock = Registry::instance().lock();
    DisplayState* d = Registry::instance().get(dpy);
    if (!d) return None;
    result = body(*d, &failure);
  }
  if (failure) {
    report(dpy, *failure, minor_opcode);
    return None;
  }
  return result;
}

XID add(DisplayState& d, std::shared_ptr<DrawableObject> object) {
  object->id = allocate_xid(d.dpy);
  XID id = object->id;
  d.drawables.emplace(id, std::move(object));
  return id;
}

XID create_pixmap(DisplayState& d, const Config* config, Pixmap pixmap,
                  std::optional<Failure>* failure) {
  int width = 0, height = 0, depth = 0;
  if (!x_drawable_size(d.dpy, pixmap, &width, &height, &depth)) {
    *failure = Failure{BadPixmap, false, pixmap};
    return None;
  }
  if (depth != config->visual_depth) {
    *failure = Failure{BadMatch, false, pixmap};
    return None;
  }
  auto object = std::make_shared<DrawableObject>();
  object->dpy = d.dpy;
  object->x_drawable = pixmap;
  object->kind = DrawableKind::Pixmap;
  object->config = config;
  object->visual = find_visual(d.dpy, config->screen, config->visual_id);
  object->x_depth = depth;
  object->gc = XCreateGC(d.dpy, pixmap, 0, nullptr);
  try {
    allocate_buffers(*object, width, height);
  } catch (const std::bad_alloc&) {
    *failure = Failure{BadAlloc, false};
    return None;
  }
  load_from_x(*object);
  return add(d, std::move(object));
}

// Destroys the GLX drawable `id` of `kind`; one current to a thread lives on until released.
void destroy(Display* dpy, XID id, DrawableKind kind, GlxError bad, GlxRequest minor_opcode) {
  std::shared_ptr<DrawableObject> doomed;  // freed after the lock is released
  with_display(dpy, minor_opcode, [&](DisplayState& d, std::optional<Failure>* f) -> XID {
    auto it = d.drawables.find(id);
    if (it == d.drawables.end() || it->second->kind != kind || it->second->implicit) {
      *f = glx_failure(bad, id);
      return None;
    }
    doomed = std::move(it->second);
    d.drawables.erase(it);
    d.retired.insert(id);
    // Destroying an X window destroyed its GLX window already.
    XWindowAttributes attributes;
    if (kind == DrawableKind::Window && !x_window_attributes(dpy, doomed->x_drawable, &attributes)) {
      *f = glx_failure(bad, id);
      return None;
    }
    return id;
  });
}

}  // namespace
}  // namespace pineda::glx

using namespace pineda::glx;

PINEDA_GLX_EXPORT GLXWindow glXCreateWindow(Display* dpy, GLXFBConfig fbconfig, Window win,
                                            const int* attribs) {
  return with_display(dpy, GlxRequest::CreateWindow, [&](DisplayState& d, std::optional<Failure>* f) -> XID {
    const Config* config = d.find_config(fbconfig);
    if (!config) {
      *f = glx_failure(GlxError::GlxFBConfig);
      return None;
    }
    XWindowAttributes attributes;
    if (!x_window_attributes(dpy, win, &attributes)) {
      *f = Failure{BadWindow, false, win};
      return None;
    }
    if (attributes.depth != config->visual_depth ||
        XScreenNumberOfScreen(attributes.screen) != config->screen) {
      *f = Failure{BadMatch, false, win};
      return None;
    }
    for (const auto& [id, object] : d.drawables)
      if (object->x_drawable == win && !object->implicit) {
        *f = Failure{BadAlloc, false, win};
        return None;
      }
    auto object = std::make_shared<DrawableObject>();
    object->dpy = dpy;
    object->x_drawable = win;
    object->kind = DrawableKind::Window;
    object->config = config;
    object->visual = attributes.visual;
    object->x_depth = attributes.depth;
    object->gc = XCreateGC(dpy, win, 0, nullptr);
    return add(d, std::move(object));
  });
}

PINEDA_GLX_EXPORT void glXDestroyWindow(Display* dpy, GLXWindow win) {
  destroy(dpy, win, DrawableKind::Window, GlxError::GlxWindow, GlxRequest::DestroyWindow);
}

PINEDA_GLX_EXPORT GLXPixmap glXCreatePixmap(Display* dpy, GLXFBConfig fbconfig, Pixmap pixmap,
                                            const int* attribs) {
  return with_display(dpy, GlxRequest::CreatePixmap, [&](DisplayState& d, std::optional<Failure>* f) -> XID {
    const Config* config = d.find_config(fbconfig);
    if (!config) {
      *f = glx_failure(GlxError::GlxFBConfig);
      return None;
    }
    return create_pixmap(d, config, pixmap, f);
  });
}

PINEDA_GLX_EXPORT void glXDestroyPixmap(Display* dpy, GLXPixmap pixmap) {
  destroy(dpy, pixmap, DrawableKind::Pixmap, GlxError::GlxPixmap, GlxRequest::DestroyPixmap);
}

PINEDA_GLX_EXPORT GLXPixmap glXCreateGLXPixmap(Display* dpy, XVisualInfo* vis, Pixmap pixmap) {
  return with_display(dpy, GlxRequest::CreateGLXPixmap, [&](DisplayState& d, std::optional<Failure>* f) -> XID {
    const Config* config = vis ? config_of_visual(d, vis->visualid) : nullptr;
    if (!config) {
      *f = Failure{BadValue, false};
      return None;
    }
    return create_pixmap(d, config, pixmap, f);
  });
}

PINEDA_GLX_EXPORT void glXDestroyGLXPixmap(Display* dpy, GLXPixmap pixmap) {
  destroy(dpy, pixmap, DrawableKind::Pixmap, GlxError::GlxPixmap, GlxRequest::DestroyGLXPixmap);
}

PINEDA_GLX_EXPORT GLXPbuffer glXCreatePbuffer(Display* dpy, GLXFBConfig fbconfig, const int* attribs) {
  return with_display(dpy, GlxRequest::CreatePbuffer, [&](DisplayState& d, std::optional<Failure>* f) -> XID {
    const Config* config = d.find_config(fbconfig);
    if (!config) {
      *f = glx_failure(GlxError::GlxFBConfig);
      return None;
    }
    int width = 0, height = 0;
    bool preserved = true, largest = false;
    for (const int* a = attribs; a && a[0] != None; a += 2) {
      switch (a[0]) {
        case GLX_PBUFFER_WIDTH: width = a[1]; break;
        case GLX_PBUFFER_HEIGHT: height = a[1]; break;
        case GLX_PRESERVED_CONTENTS: preserved = a[1] != False; break;
        case GLX_LARGEST_PBUFFER: largest = a[1] != False; break;
        default: *f = Failure{BadValue, false}; return None;
      }
    }
    if (width < 0 || height < 0) {
      *f = Failure{BadValue, false};
      return None;
    }
    if (width > kMaxDrawableSize || height > kMaxDrawableSize) {
      if (!largest) {
        *f = Failure{BadAlloc, false};
        return None;
      }
      width = std::min(width, kMaxDrawableSize);
      height = std::min(height, kMaxDrawableSize);
    }
    auto object = std::make_shared<DrawableObject>();
    object->dpy = dpy;
    object->kind = DrawableKind::Pbuffer;
    object->config = config;
    object->preserved_contents = preserved;
    object->largest_pbuffer = largest;
    try {
      allocate_buffers(*object, width, height);
    } catch (const std::bad_alloc&) {
      *f = Failure{BadAlloc, false};
      return None;
    }
    return add(d, std::move(object));
  });
}

PINEDA_GLX_EXPORT void glXDestroyPbuffer(Display* dpy, GLXPbuffer pbuffer) {
  destroy(dpy, pbuffer, DrawableKind::Pbuffer, GlxError::GlxPbuffer, GlxRequest::DestroyPbuffer);
}

PINEDA_GLX_EXPORT void glXQueryDrawable(Display* dpy, GLXDrawable draw, int attribute,
                                        unsigned int* value) {
  std::shared_ptr<DrawableObject> object;
  {
    auto lock = Registry::instance().lock();
    object = Registry::instance().find_drawable(dpy, draw);
  }
  if (!object || !value) {
    send_glx_error(dpy, GlxError::GlxDrawable, GlxRequest::GetDrawableAttributes, draw);
    return;
  }
  int width = object->width, height = object->height;
  if (object->kind == DrawableKind::Window) x_drawable_size(dpy, object->x_drawable, &width, &height);
  switch (attribute) {
    case GLX_WIDTH: *value = width; break;
    case GLX_HEIGHT: *value = height; break;
    case GLX_PRESERVED_CONTENTS: *value = object->preserved_contents; break;
    case GLX_LARGEST_PBUFFER: *value = object->largest_pbuffer; break;
    case GLX_FBCONFIG_ID: *value = object->config->id; break;
    case GLX_EVENT_MASK: *value = object->event_mask; break;
    case GLX_SWAP_INTERVAL_EXT: *value = object->swap_interval; break;
    case GLX_MAX_SWAP_INTERVAL_EXT: *value = 1000; break;
    default: send_x_error(dpy, BadValue, GlxRequest::GetDrawableAttributes, draw); break;
  }
}

PINEDA_GLX_EXPORT void glXSelectEvent(Display* dpy, GLXDrawable draw, unsigned long mask) {
  std::shared_ptr<DrawableObject> object;
  {
    auto lock = Registry::instance().lock();
    object = Registry::instance().find_drawable(dpy, draw);
    // Pineda's buffers are never clobbered: GLX_PBUFFER_CLOBBER_MASK is kept, never sent.
    if (object) object->event_mask = mask;
  }
  if (!object) send_glx_error(dpy, GlxError::GlxDrawable, GlxRequest::ChangeDrawableAttributes, draw);
}

PINEDA_GLX_EXPORT void glXGetSelectedEvent(Display* dpy, GLXDrawable draw, unsigned long* mask) {
  std::shared_ptr<DrawableObject> object;
  {
    auto lock = Registry::instance().lock();
    object = Registry::instance().find_drawable(dpy, draw);
    if (object && mask) *mask = object->event_mask;
  }
  if (!object) send_glx_error(dpy, GlxError::GlxDrawable, GlxRequest::GetDrawableAttributes, draw);
}
