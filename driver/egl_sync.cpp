// EGL 1.5 fence syncs. Creating a fence completes the context's rendering (glFinish), so
// every fence is signaled and waits return at once.
#include "driver/egl_registry.h"
#include "driver/egl_thread.h"
#include "glapi/egl_entry_points.h"

namespace pineda::egl {
namespace {

// Caller holds the lock. nullptr after recording the error.
Sync* find_sync(EGLDisplay dpy, EGLSync sync) {
  Display* display = initialized_display(dpy);
  if (!display) return nullptr;
  auto it = display->syncs.find(sync);
  if (it == display->syncs.end()) return fail<Sync*>(EGL_BAD_PARAMETER, nullptr);
  return it->second.get();
}

}  // namespace

EGLSync CreateSync(EGLDisplay dpy, EGLenum type, const EGLAttrib* attrib_list) {
  auto lock = Registry::instance().lock();
  Display* display = initialized_display(dpy);
  if (!display) return EGL_NO_SYNC;
  if (type != EGL_SYNC_FENCE) return fail(EGL_BAD_PARAMETER, EGL_NO_SYNC);
  if (attrib_list && attrib_list[0] != EGL_NONE) return fail(EGL_BAD_ATTRIBUTE, EGL_NO_SYNC);
  ThreadState& t = thread_state();
  if (!t.context || t.display != display) return fail(EGL_BAD_MATCH, EGL_NO_SYNC);
  auto sync = std::make_unique<Sync>();
  EGLSync handle = sync.get();
  display->syncs.emplace(handle, std::move(sync));
  lock.unlock();
  t.context->gl->finish_for_reading();
  return succeed(handle);
}

EGLBoolean DestroySync(EGLDisplay dpy, EGLSync sync) {
  auto lock = Registry::instance().lock();
  if (!find_sync(dpy, sync)) return EGL_FALSE;
  Registry::instance().find(dpy)->syncs.erase(sync);
  return succeed(EGL_TRUE);
}

EGLint ClientWaitSync(EGLDisplay dpy, EGLSync sync, EGLint flags, EGLTime timeout) {
  auto lock = Registry::instance().lock();
  if (!find_sync(dpy, sync)) return EGL_FALSE;
  return succeed<EGLint>(EGL_CONDITION_SATISFIED);
}

EGLBoolean WaitSync(EGLDisplay dpy, EGLSync sync, EGLint flags) {
  auto lock = Registry::instance().lock();
  if (!find_sync(dpy, sync)) return EGL_FALSE;
  if (flags != 0) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  ThreadState& t = thread_state();
  if (!t.context || t.display != Registry::instance().find(dpy))
    return fail(EGL_BAD_MATCH, EGL_FALSE);
  return succeed(EGL_TRUE);
}

EGLBoolean GetSyncAttrib(EGLDisplay dpy, EGLSync sync, EGLint attribute, EGLAttrib* value) {
  auto lock = Registry::instance().lock();
  Sync* s = find_sync(dpy, sync);
  if (!s) return EGL_FALSE;
  EGLAttrib result;
  switch (attribute) {
    case EGL_SYNC_TYPE: result = s->type; break;
    case EGL_SYNC_STATUS: result = EGL_SIGNALED; break;
    case EGL_SYNC_CONDITION: result = EGL_SYNC_PRIOR_COMMANDS_COMPLETE; break;
    default: return fail(EGL_BAD_ATTRIBUTE, EGL_FALSE);
  }
  if (!value) return fail(EGL_BAD_PARAMETER, EGL_FALSE);
  *value = result;
  return succeed(EGL_TRUE);
}

}  // namespace pineda::egl
