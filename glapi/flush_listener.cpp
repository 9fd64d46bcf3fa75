#include "glapi/flush_listener.h"

namespace pineda::glapi {
namespace {
struct Registration {
  Context* ctx = nullptr;
  FlushListener* listener = nullptr;
};
thread_local Registration registration;
}  // namespace

void set_flush_listener(Context* ctx, FlushListener* listener) {
  registration = listener ? Registration{ctx, listener} : Registration{};
}

void notify_flushed(Context& ctx) {
  if (registration.listener && registration.ctx == &ctx) registration.listener->flushed();
}

}  // namespace pineda::glapi
