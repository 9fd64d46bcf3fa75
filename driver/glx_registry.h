// The process-wide table of X displays Pineda's GLX has seen (and through them contexts,
// drawables and configs), behind one mutex. A display's state is dropped when the
// application closes the display (XCloseDisplay).
#pragma once
#include <mutex>

#include "driver/glx_objects.h"

namespace pineda::glx {

class Registry {
 public:
  static Registry& instance();

  std::unique_lock<std::mutex> lock() { return std::unique_lock(mutex_); }

  // Caller holds the lock. The state of `dpy`, created on first use (this talks to the
  // server: extension codes and visuals). nullptr only when `dpy` is null.
  DisplayState* get(Display* dpy);
  // Caller holds the lock.
  void forget(Display* dpy);
  // Caller holds the lock. The GLX drawable `id` of `dpy`'s server: GLX drawables are
  // server resources, usable through every connection to that server.
  std::shared_ptr<DrawableObject> find_drawable(Display* dpy, XID id);

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<DisplayState>> displays_;
};

// A new XID from the client's range, for a GLX drawable that exists only in this library.
XID allocate_xid(Display* dpy);

}  // namespace pineda::glx
