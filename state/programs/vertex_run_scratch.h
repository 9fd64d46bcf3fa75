// Room for a draw's vertex-shader run, kept in the context from draw to draw: a draw of a few
// vertices allocated and zeroed its inputs, outputs and uniform values each time, a third of
// what such a draw cost on the calling thread (glsl_many_draws).
#pragma once
#include <vector>

#include "shader/program.h"
#include "state/programs/generic_attribs.h"
#include "state/state_key.h"

namespace pineda {

// Where one vec4 input slot of the vertex shader comes from, found once per draw.
struct InputFetch {
  int slot = 0;
  shader::BuiltinAttribute builtin = shader::BuiltinAttribute::None;
  int location = 0;        // generic attribute, when not built-in
  bool from_view = false;  // an array read directly: `view`
  DirectArrayView view;
};

struct VertexRunScratch {
  std::vector<InputFetch> fetches;
  StateKey fetches_state;  // the state and source they were found for (state/state_key.h)
  AttribSource fetches_source = AttribSource::Arrays;
  // Every input slot has a fetch, which writes its four components for each vertex: the lanes
  // past a draw's last vertex may keep an earlier draw's values (their outputs are not read).
  bool fetches_fill_slots = false;
  // The inputs and outputs of the batches run at once, for a draw run on the calling thread
  // alone (a draw of more pieces allocates them per piece).
  std::vector<float> in, result;
};

}  // namespace pineda
