// Per-thread EGL state: the last error, the bound API and the current binding.
#pragma once
#include <memory>

#include "driver/egl_objects.h"
#include "driver/gl_version.h"
#include "glapi/flush_listener.h"

namespace pineda::egl {

// EGL 1.5, 3.7: OpenGL ES when it is supported, otherwise none.
inline constexpr EGLenum kInitialApi = driver::kHasGLES ? EGL_OPENGL_ES_API : EGL_NONE;

struct ThreadState final : glapi::FlushListener {
  EGLint error = EGL_SUCCESS;
  EGLenum api = kInitialApi;
  Display* display = nullptr;
  EGLContext context_handle = EGL_NO_CONTEXT;
  EGLSurface draw_handle = EGL_NO_SURFACE, read_handle = EGL_NO_SURFACE;
  std::shared_ptr<ContextObject> context;
  std::shared_ptr<Surface> draw, read;

  // glFlush/glFinish: front-buffer drawing in a window or pixmap surface becomes visible.
  void flushed() override;
  // A thread that ends with a current context releases it.
  ~ThreadState();
};

ThreadState& thread_state();

// Releases the calling thread's current context, if any (takes the registry lock).
void release_current_binding();
// The same, given the calling thread's state (also while it is being destroyed).
void release_binding(ThreadState& t);

template <class T>
T fail(EGLint error, T result) {
  thread_state().error = error;
  return result;
}

template <class T>
T succeed(T result) {
  thread_state().error = EGL_SUCCESS;
  return result;
}

}  // namespace pineda::egl
