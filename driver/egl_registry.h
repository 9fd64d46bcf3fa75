// The process-wide table of displays (and through them contexts and surfaces), behind one
// mutex. Displays live until the process ends: a handle stays comparable after Terminate.
#pragma once
#include <mutex>
#include <vector>

#include "driver/egl_objects.h"

namespace pineda::egl {

class Registry {
 public:
  static Registry& instance();

  std::unique_lock<std::mutex> lock() { return std::unique_lock(mutex_); }

  // Caller holds the lock. The display of (platform, native), created on first use.
  Display* get(EGLenum platform, void* native);
  // Caller holds the lock. nullptr when `handle` is not a display.
  Display* find(EGLDisplay handle) const;

 private:
  std::mutex mutex_;
  std::vector<std::unique_ptr<Display>> displays_;
};

// Caller holds the lock. Returns the display, or records EGL_BAD_DISPLAY (not a display) or
// EGL_NOT_INITIALIZED and returns nullptr.
Display* initialized_display(EGLDisplay handle);

}  // namespace pineda::egl
