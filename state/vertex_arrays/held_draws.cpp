#include "state/vertex_arrays/held_draws.h"

#include <new>
#include <stdexcept>
#include <utility>

#include "state/context.h"
#include "state/draw.h"
#include "state/vertex_arrays/array_elements.h"

namespace pineda {
namespace {

// At most this many vertices wait: a run's vertex outputs, windows and varyings then stay in the
// cache from one stage to the next (glsl_small_draws, one thread: 7.05 ms a frame with 65536,
// 6.22 with 4096, medians of five; 2048 and 8192 about as 4096, 1024 slower).
constexpr size_t kMaxHeldElements = 4096;

}  // namespace

bool may_hold_back(const Context& ctx, GLenum mode, GLsizei count) {
  const HeldDraws& held = ctx.held_draws;
  if (mode != GL_TRIANGLES || count % 3 != 0 || held.ready_state != ctx.state_key()) return false;
  // Another context of the group could change a buffer the held draws read before they run.
  if (ctx.share_group()->members.load(std::memory_order_relaxed) > 1) return false;
  return held.elements.size() + static_cast<size_t>(count) <= kMaxHeldElements;
}

void note_draw_ran(Context& ctx, GLenum mode, bool clean) {
  HeldDraws& held = ctx.held_draws;
  const StateKey key = ctx.state_key();
  // Client memory may change between the calls without a GL call; lists, feedback and
  // selection draw their own ways. The arrays' check (arrays_ready) must be of this state.
  const bool ready = clean && mode == GL_TRIANGLES && ctx.list_depth == 0 && !ctx.compiling_list() &&
                     ctx.render_mode.mode == GL_RENDER && ctx.arrays_known_ready.state == key &&
                     !ctx.arrays_known_ready.client_memory;
  held.ready_state = ready ? key : StateKey{};
}

void draw_held_back(Context& ctx) {
  // Taken out first: the draw may note a change of state, which would draw them again.
  std::vector<uint32_t> elements;
  elements.swap(ctx.held_draws.elements);
  const char* const call = std::exchange(ctx.current_call, "glDrawArrays");
  try {
    draw_array_vertices(ctx, GL_TRIANGLES,
                        array_elements(ctx, elements.size(), [&elements](size_t i) { return size_t{elements[i]}; }), {});
  } catch (const std::bad_alloc&) {  // (count_state_call runs before an entry point's try block)
    ctx.record_error(GL_OUT_OF_MEMORY, "the memory this call needs could not be allocated");
  } catch (const std::length_error&) {
    ctx.record_error(GL_OUT_OF_MEMORY, "the memory this call needs could not be allocated");
  }
  ctx.current_call = call;
  elements.clear();
  if (ctx.held_draws.elements.empty()) ctx.held_draws.elements.swap(elements);  // its room, for the next ones
}

}  // namespace pineda
