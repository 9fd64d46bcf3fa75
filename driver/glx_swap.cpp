// glXSwapBuffers, the swap-interval extensions (GLX_EXT_swap_control, GLX_MESA_swap_control,
// GLX_SGI_swap_control), glXWaitGL and glXWaitX.
//
// The swap interval is recorded and reported; swaps are not paced, because an X server
// tells a plain Xlib client nothing of vertical retrace.
#include "driver/glx_current.h"

#include "driver/glx_drawable.h"
#include "driver/glx_error.h"
#include "driver/glx_registry.h"

namespace pineda::glx {
namespace {

std::shared_ptr<DrawableObject> find(Display* dpy, GLXDrawable id, int* bindings) {
  auto lock = Registry::instance().lock();
  auto object = Registry::instance().find_drawable(dpy, id);
  if (object && bindings) *bindings = object->bindings;
  return object;
}

// After a swap the window may have been resized: the next frame renders at the new size.
void follow_resize(ThreadState& t, DrawableObject& d, int bindings) {
  if (d.kind != DrawableKind::Window || !d.dpy) return;
  const bool mine = t.draw.get() == &d || t.read.get() == &d;
  // Buffers that another thread renders to are left alone.
  if (bindings > (mine ? 1 : 0)) return;
  int width = 0, height = 0;
  if (!x_drawable_size(d.dpy, d.x_drawable, &width, &height)) return;
  if (width == d.width && height == d.height) return;
  try {
    allocate_buffers(d, width, height);
  } catch (const std::bad_alloc&) {
    return;  // keeps rendering at the old size
  }
  if (mine) t.context->gl->drawable_changed();
}

}  // namespace
}  // namespace pineda::glx

using namespace pineda::glx;

PINEDA_GLX_EXPORT void glXSwapBuffers(Display* dpy, GLXDrawable drawable) {
  int bindings = 0;
  std::shared_ptr<DrawableObject> d = find(dpy, drawable, &bindings);
  if (!d) {
    send_glx_error(dpy, GlxError::GlxDrawable, GlxRequest::SwapBuffers, drawable);
    return;
  }
  ThreadState& t = thread_state();
  const bool mine = t.draw == d || t.read == d;
  if (mine) t.context->gl->finish_for_reading();  // the implicit glFlush
  // Single-buffered drawables and pixmaps are unaffected.
  if (d->drawable.double_buffered) swap_and_present(*d);
  else if (mine) flush_front(t, false);
  follow_resize(t, *d, bindings);
}

PINEDA_GLX_EXPORT void glXSwapIntervalEXT(Display* dpy, GLXDrawable drawable, int interval) {
  if (interval < 0) {
    send_x_error(dpy, BadValue, GlxRequest::SwapBuffers);
    return;
  }
  std::shared_ptr<DrawableObject> d = find(dpy, drawable, nullptr);
  if (!d) {
    send_x_error(dpy, BadWindow, GlxRequest::SwapBuffers, drawable);
    return;
  }
  auto lock = Registry::instance().lock();
  d->swap_interval = interval;
}

PINEDA_GLX_EXPORT int glXSwapIntervalMESA(unsigned int interval) {
  ThreadState& t = thread_state();
  if (!t.context || !t.draw) return GLX_BAD_CONTEXT;
  if (interval > 0x7fffffff) return GLX_BAD_VALUE;
  auto lock = Registry::instance().lock();
  t.draw->swap_interval = static_cast<int>(interval);
  return 0;
}

PINEDA_GLX_EXPORT int glXSwapIntervalSGI(int interval) {
  ThreadState& t = thread_state();
  if (interval <= 0) return GLX_BAD_VALUE;
  if (!t.context || !t.draw) return GLX_BAD_CONTEXT;
  auto lock = Registry::instance().lock();
  t.draw->swap_interval = interval;
  return 0;
}

PINEDA_GLX_EXPORT int glXGetSwapIntervalMESA(void) {
  ThreadState& t = thread_state();
  if (!t.draw) return 0;
  auto lock = Registry::instance().lock();
  return t.draw->swap_interval;
}

PINEDA_GLX_EXPORT void glXWaitGL(void) { flush_front(thread_state(), false); }

PINEDA_GLX_EXPORT void glXWaitX(void) {
  ThreadState& t = thread_state();
  if (!t.context || !t.dpy) return;
  XSync(t.dpy, False);
  // X drawing into a pixmap becomes part of its GL colour buffer. (A window cannot be read
  // back reliably: parts of it may be covered or off-screen.)
  if (t.draw && t.draw->kind == DrawableKind::Pixmap) {
    t.context->gl->finish();
    load_from_x(*t.draw);
  }
}
