// Consecutive glDrawArrays(GL_TRIANGLES) calls with nothing changed between them, run as one
// draw: a program of many small draws pays the vertex stage, the draw's set-up and the
// renderer's per-draw work once per run of them instead of once per call (glsl_small_draws'
// 20000 calls of one triangle each). A held-back draw runs before anything that could tell:
// every GL call but the draws and glGetError (Context::count_state_call), any other change of
// state (Context::note_state_changed), another draw, and every finish (glFinish, glFlush,
// swaps, reading the framebuffer).
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "state/state_key.h"

namespace pineda {

class Context;

struct HeldDraws {
  std::vector<uint32_t> elements;  // the held-back triangles' array elements, in order
  // Set by a glDrawArrays that ran at once in state `ready_state` without recording an error
  // (so that a held-back call records each error its own run would at the call): while the
  // state stays that, the next such calls may be held back.
  bool ready = false;
  StateKey ready_state;
};

// Takes glDrawArrays(mode, first, count), its checks passed, as a held-back draw when it may
// be; false when it must run now.
bool hold_back_draw(Context& ctx, GLenum mode, GLint first, GLsizei count);

// After glDrawArrays ran a draw at once: whether the calls after it, in the state it left,
// may be held back (`clean`: it recorded no error).
void note_draw_ran(Context& ctx, GLenum mode, bool clean);

// Runs the held-back draws, if any, as one draw of GL_TRIANGLES.
void draw_held_back(Context& ctx);

}  // namespace pineda
