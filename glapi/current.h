// The current context of the calling thread: the one piece of global mutable state.
#pragma once

namespace pineda {

class Context;

Context* current_context();
void set_current_context(Context* ctx);

}  // namespace pineda
