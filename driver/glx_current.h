// The calling thread's GLX binding: context, draw and read drawables.
#pragma once
#include "driver/glx_error.h"
#include "glapi/flush_listener.h"

namespace pineda::glx {

struct ThreadState final : glapi::FlushListener {
  Display* dpy = nullptr;
  GLXContext context_handle = nullptr;
  GLXDrawable draw_id = None, read_id = None;
  std::shared_ptr<ContextObject> context;
  std::shared_ptr<DrawableObject> draw, read;

  // glFlush/glFinish: what is drawn to a front buffer becomes visible.
  void flushed() override;
  // A thread that ends with a current context releases it (without touching the server).
  ~ThreadState();
};

ThreadState& thread_state();

// Completes the current context's rendering and shows front-buffer drawing: the buffer of a
// single-buffered window or pixmap, or a double-buffered window drawn with GL_FRONT.
// `checked`: for the implicit flush of glXMakeCurrent, when the application may already have
// destroyed the window (X errors are caught, at the cost of a round trip).
void flush_front(ThreadState& t, bool checked);

// glXMakeContextCurrent (and glXMakeCurrent with draw == read). Reports errors through
// the X error path with `minor_opcode`.
Bool make_current(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx,
                  GlxRequest minor_opcode);

}  // namespace pineda::glx
