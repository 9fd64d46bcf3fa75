#include "driver/egl_registry.h"

#include "driver/egl_thread.h"

namespace pineda::egl {

Registry& Registry::instance() {
  // Never destroyed: threads that end after main() returns may still release through it.
  static Registry* registry = new Registry;
  return *registry;
}

Display* Registry::get(EGLenum platform, void* native) {
  for (auto& d : displays_)
    if (d->platform == platform && d->native == native) return d.get();
  displays_.push_back(std::make_unique<Display>());
  displays_.back()->platform = platform;
  displays_.back()->native = native;
  return displays_.back().get();
}

Display* Registry::find(EGLDisplay handle) const {
  for (auto& d : displays_)
    if (d.get() == handle) return d.get();
  return nullptr;
}

Display* initialized_display(EGLDisplay handle) {
  Display* display = Registry::instance().find(handle);
  if (!display) return fail<Display*>(EGL_BAD_DISPLAY, nullptr);
  if (!display->initialized) return fail<Display*>(EGL_NOT_INITIALIZED, nullptr);
  return display;
}

}  // namespace pineda::egl
