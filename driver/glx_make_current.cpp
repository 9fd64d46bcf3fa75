// glXMakeCurrent, glXMakeContextCurrent and the glXGetCurrent* queries.
#include "driver/glx_current.h"

using namespace pineda::glx;

PINEDA_GLX_EXPORT Bool glXMakeCurrent(Display* dpy, GLXDrawable drawable, GLXContext ctx) {
  return make_current(dpy, drawable, drawable, ctx, GlxRequest::MakeCurrent);
}

PINEDA_GLX_EXPORT Bool glXMakeContextCurrent(Display* dpy, GLXDrawable draw, GLXDrawable read,
                                             GLXContext ctx) {
  return make_current(dpy, draw, read, ctx, GlxRequest::MakeContextCurrent);
}

PINEDA_GLX_EXPORT GLXContext glXGetCurrentContext(void) { return thread_state().context_handle; }

PINEDA_GLX_EXPORT GLXDrawable glXGetCurrentDrawable(void) { return thread_state().draw_id; }

PINEDA_GLX_EXPORT GLXDrawable glXGetCurrentReadDrawable(void) { return thread_state().read_id; }

PINEDA_GLX_EXPORT Display* glXGetCurrentDisplay(void) { return thread_state().dpy; }
