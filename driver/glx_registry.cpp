#include "driver/glx_registry.h"


#include <string>

#include "driver/glx_config.h"

// Last: Xlib's internal header (for XESetCloseDisplay) defines min and max macros.
#include <X11/Xlibint.h>

namespace pineda::glx {
namespace {

int on_close_display(Display* dpy, XExtCodes*) {
  Registry& registry = Registry::instance();
  auto lock = registry.lock();
  registry.forget(dpy);
  return 0;
}

}  // namespace

Registry& Registry::instance() {
  // Never destroyed: threads that end after main() returns may still release through it.
  static Registry* registry = new Registry;
  return *registry;
}

DisplayState* Registry::get(Display* dpy) {
  if (!dpy) return nullptr;
  for (auto& d : displays_)
    if (d->dpy == dpy) return d.get();
  auto d = std::make_unique<DisplayState>();
  d->dpy = dpy;
  d->server_glx = XQueryExtension(dpy, "GLX", &d->major_opcode, &d->event_base, &d->error_base);
  d->configs = build_configs(dpy);
  // A client-side extension record, only to hear XCloseDisplay.
  if (XExtCodes* codes = XAddExtension(dpy)) XESetCloseDisplay(dpy, codes->extension, on_close_display);
  displays_.push_back(std::move(d));
  return displays_.back().get();
}

std::shared_ptr<DrawableObject> Registry::find_drawable(Display* dpy, XID id) {
  DisplayState* own = get(dpy);
  if (!own) return nullptr;
  if (auto found = own->find_drawable(id)) return found;
  const std::string server = XDisplayString(dpy);
  for (auto& d : displays_)
    if (d.get() != own && server == XDisplayString(d->dpy))
      if (auto found = d->find_drawable(id)) return found;
  return nullptr;
}

void Registry::forget(Display* dpy) {
  for (auto it = displays_.begin(); it != displays_.end(); ++it) {
    if ((*it)->dpy != dpy) continue;
    // The connection is going away (it is still usable in this hook); drawables still
    // current elsewhere keep their memory but must not touch the server again.
    for (auto& [id, drawable] : (*it)->drawables) {
      if (drawable->gc) XFreeGC(dpy, drawable->gc);
      drawable->gc = nullptr;
      drawable->dpy = nullptr;
      if (drawable->shm) drawable->shm->forget_display();
    }
    displays_.erase(it);
    return;
  }
}

XID allocate_xid(Display* dpy) {
  // Xlib refills its next id while the display is locked, as its own requests do.
  LockDisplay(dpy);
  XID id = XAllocID(dpy);
  UnlockDisplay(dpy);
  return id;
}

}  // namespace pineda::glx
