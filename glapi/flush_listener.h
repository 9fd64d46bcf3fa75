// A window-system binding whose user-visible buffer is a converted copy of the drawable
// (OSMesa's 3-byte formats) must learn when GL has finished rendering: glFinish and glFlush
// notify the listener registered for the calling thread's current context.
#pragma once

namespace pineda {
class Context;
}

namespace pineda::glapi {

class FlushListener {
 public:
  virtual void flushed() = 0;

 protected:
  ~FlushListener() = default;
};

// Per thread: `listener` hears flushes of `ctx` only. nullptr unregisters.
void set_flush_listener(Context* ctx, FlushListener* listener);
void notify_flushed(Context& ctx);

}  // namespace pineda::glapi
