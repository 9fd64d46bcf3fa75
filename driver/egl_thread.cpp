#include "driver/egl_thread.h"

#include "driver/egl_registry.h"
#include "driver/egl_x11.h"
#include "driver/thread_slot.h"
#include "glapi/current.h"

namespace pineda::egl {

ThreadState& thread_state() { return driver::thread_slot<ThreadState>(); }

ThreadState::~ThreadState() {
  if (context) release_binding(*this);
}

void ThreadState::flushed() {
  if (draw) show_front(*draw);
}

void release_current_binding() { release_binding(thread_state()); }

void release_binding(ThreadState& t) {
  std::shared_ptr<ContextObject> context = std::move(t.context);
  std::shared_ptr<Surface> draw = std::move(t.draw), read = std::move(t.read);
  t.display = nullptr;
  t.context_handle = EGL_NO_CONTEXT;
  t.draw_handle = t.read_handle = EGL_NO_SURFACE;
  if (!context) return;
  // The GL side lets go first: until ownership is handed back no other thread can bind it.
  context->gl->release_current();
  glapi::set_flush_listener(nullptr, nullptr);
  set_current_context(nullptr);
  {
    auto lock = Registry::instance().lock();
    context->bound_thread = nullptr;
    context->bound_to_surface = false;
    if (draw) draw->bound_thread = nullptr;
    if (read) read->bound_thread = nullptr;
  }
  // The references drop here: a destroyed context or surface is freed now.
}

}  // namespace pineda::egl
