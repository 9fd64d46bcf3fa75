// eglMakeCurrent (with EGL_KHR_surfaceless_context), eglGetCurrentContext/Surface/Display,
// eglReleaseThread, eglWaitGL/WaitClient/WaitNative.
#include <utility>

#include "driver/egl_registry.h"
#include "driver/egl_thread.h"
#include "driver/egl_x11.h"
#include "glapi/current.h"
#include "glapi/flush_listener.h"
#include "glapi/egl_entry_points.h"

namespace pineda::egl {
namespace {

bool compatible(const Config& a, const Config& b) {
  return a.red == b.red && a.green == b.green && a.blue == b.blue && a.alpha == b.alpha &&
         a.depth == b.depth && a.stencil == b.stencil;
}

bool bound_elsewhere(const ThreadState* owner, const ThreadState& me) {
  return owner != nullptr && owner != &me;
}

}  // namespace

EGLBoolean MakeCurrent(EGLDisplay dpy, EGLSurface draw, EGLSurface read, EGLContext ctx) {
  ThreadState& t = thread_state();
  auto lock = Registry::instance().lock();
  Display* display = Registry::instance().find(dpy);
  if (!display) return fail(EGL_BAD_DISPLAY, EGL_FALSE);
  bool releasing = ctx == EGL_NO_CONTEXT;
  if (releasing) {
    if (draw != EGL_NO_SURFACE || read != EGL_NO_SURFACE) return fail(EGL_BAD_MATCH, EGL_FALSE);
    // Releasing is allowed on a terminated display, so that its objects can be freed.
    lock.unlock();
    release_current_binding();
    return succeed(EGL_TRUE);
  }
  if (!display->initialized) return fail(EGL_NOT_INITIALIZED, EGL_FALSE);
  auto context = display->find_context(ctx);
  if (!context) return fail(EGL_BAD_CONTEXT, EGL_FALSE);
  if ((draw == EGL_NO_SURFACE) != (read == EGL_NO_SURFACE)) return fail(EGL_BAD_MATCH, EGL_FALSE);
  std::shared_ptr<Surface> draw_surface, read_surface;
  if (draw != EGL_NO_SURFACE) {
    draw_surface = display->find_surface(draw);
    read_surface = display->find_surface(read);
    if (!draw_surface || !read_surface) return fail(EGL_BAD_SURFACE, EGL_FALSE);
  }
  if (bound_elsewhere(context->bound_thread, t)) return fail(EGL_BAD_ACCESS, EGL_FALSE);
  for (const auto& s : {draw_surface, read_surface}) {
    if (!s) continue;
    if (bound_elsewhere(s->bound_thread, t)) return fail(EGL_BAD_ACCESS, EGL_FALSE);
    if (!compatible(*s->config, *context->config)) return fail(EGL_BAD_MATCH, EGL_FALSE);
    if (!follow_native_size(*s)) return fail(EGL_BAD_NATIVE_WINDOW, EGL_FALSE);
  }

  // Claim the new binding. The old one stays this thread's until its GL side has let go,
  // so that no other thread can bind it while it is still being released.
  context->bound_thread = &t;
  context->bound_to_surface = draw_surface != nullptr;
  if (draw_surface) draw_surface->bound_thread = &t;
  if (read_surface) read_surface->bound_thread = &t;
  lock.unlock();

  std::shared_ptr<ContextObject> old_context = std::exchange(t.context, context);
  std::shared_ptr<Surface> old_draw = std::exchange(t.draw, draw_surface);
  std::shared_ptr<Surface> old_read = std::exchange(t.read, read_surface);
  t.display = display;
  t.context_handle = ctx;
  t.draw_handle = draw;
  t.read_handle = read;
  if (old_context && old_context != context) old_context->gl->release_current();
  set_current_context(context->gl.get());
  context->gl->make_current(draw_surface ? draw_surface->gl_drawable() : nullptr,
                            read_surface ? read_surface->gl_drawable() : nullptr);
  glapi::set_flush_listener(context->gl.get(), &t);

  // Hand back what the new binding does not use.
  lock.lock();
  if (old_context && old_context != context) {
    old_context->bound_thread = nullptr;
    old_context->bound_to_surface = false;
  }
  for (const auto& s : {old_draw, old_read})
    if (s && s != draw_surface && s != read_surface) s->bound_thread = nullptr;
  lock.unlock();
  return succeed(EGL_TRUE);
}

EGLContext GetCurrentContext() { return succeed(thread_state().context_handle); }

EGLDisplay GetCurrentDisplay() {
  ThreadState& t = thread_state();
  return succeed<EGLDisplay>(t.context ? t.display : EGL_NO_DISPLAY);
}

EGLSurface GetCurrentSurface(EGLint readdraw) {
  ThreadState& t = thread_state();
  if (readdraw == EGL_DRAW) return succeed(t.draw_handle);
  if (readdraw == EGL_READ) return succeed(t.read_handle);
  return fail(EGL_BAD_PARAMETER, EGL_NO_SURFACE);
}

EGLBoolean ReleaseThread() {
  release_current_binding();
  thread_state().api = kInitialApi;
  return succeed(EGL_TRUE);
}

EGLBoolean WaitClient() {
  ThreadState& t = thread_state();
  if (t.context) t.context->gl->finish();
  if (t.context && t.draw) show_front(*t.draw);
  return succeed(EGL_TRUE);
}

EGLBoolean WaitGL() { return WaitClient(); }

EGLBoolean WaitNative(EGLint engine) {
  // There is no native rendering to wait for.
  if (engine != EGL_CORE_NATIVE_ENGINE) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  return succeed(EGL_TRUE);
}

}  // namespace pineda::egl
