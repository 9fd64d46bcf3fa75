#include "glapi/current.h"

namespace pineda {
namespace {
thread_local Context* current = nullptr;
}

Context* current_context() { return current; }
void set_current_context(Context* ctx) { current = ctx; }

}  // namespace pineda
