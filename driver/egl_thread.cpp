#include "driver/egl_thread.h"

#include "driver/egl_registry.h"
#include "glapi/current.h"

namespace pineda::egl {

ThreadState& thread_state() {
  thread_local ThreadState state;
  return state;
}

ThreadState::~ThreadState() {
  if (context) release_current_binding();
}

void release_current_binding() {
  ThreadState& t = thread_state();
  std::shared_ptr<ContextObject> context = std::move(t.context);
  std::shared_ptr<Surface> draw = std::move(t.draw), read = std::move(t.read);
  {
    auto lock = Registry::instance().lock();
    if (context) {
      context->bound_thread = nullptr;
      context->bound_to_surface = false;
    }
    if (draw) draw->bound_thread = nullptr;
    if (read) read->bound_thread = nullptr;
    t.display = nullptr;
    t.context_handle = EGL_NO_CONTEXT;
    t.draw_handle = t.read_handle = EGL_NO_SURFACE;
  }
  if (context) {
    context->gl->release_current();
    set_current_context(nullptr);
  }
  // The references drop here: a destroyed context or surface is freed now.
}

}  // namespace pineda::egl
