// Consecutive glDrawArrays and glDrawElements calls of GL_TRIANGLES with nothing changed
// between them, run as one draw: a program of many small draws pays the vertex stage, the draw's
// set-up and the renderer's per-draw work once per run of them instead of once per call
// (glsl_small_draws' 20000 calls of one triangle each). A held-back draw runs before anything
// that could tell: every GL call but the draws and glGetError (Context::count_state_call), any
// other change of state (Context::note_state_changed), another draw that is not held, and every
// finish (glFinish, glFlush, swaps, reading the framebuffer).
#pragma once
#include <GL/gl.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "state/state_key.h"

namespace pineda {

class Context;

struct HeldDraws {
  std::vector<uint32_t> elements;  // the held-back triangles' array elements, in order
  // The state in which a glDrawArrays or glDrawElements that may be followed by held calls ran
  // at once without recording an error (so that a held-back call records each error its own run
  // would at the call): while the state stays that, the next such calls may be held back. A
  // default key, which matches no state, when none may.
  StateKey ready_state;
};

// Whether a glDrawArrays or glDrawElements of `count` vertices in `mode`, its checks passed,
// may be held back (hold_back) rather than run now.
bool may_hold_back(const Context& ctx, GLenum mode, GLsizei count);

// An indexed draw is held back only up to this many indices: held draws run every index's
// vertex through the vertex stage, where a draw of its own runs each vertex it names once.
constexpr GLsizei kMaxHeldIndices = 96;

// Holds back the vertices of such a draw: array elements element_of(i), i < count, clamped as
// array_elements clamps them.
template <typename ElementOf>
void hold_back(HeldDraws& held, GLsizei count, ElementOf element_of) {
  for (GLsizei i = 0; i < count; ++i)
    held.elements.push_back(static_cast<uint32_t>(std::min<size_t>(element_of(i), UINT32_MAX - 1)));
}

// After a glDrawArrays or glDrawElements ran at once: whether the calls after it, in the state
// it left, may be held back (`clean`: it recorded no error).
void note_draw_ran(Context& ctx, GLenum mode, bool clean);

// Runs the held-back draws, if any, as one draw of GL_TRIANGLES.
void draw_held_back(Context& ctx);

}  // namespace pineda
