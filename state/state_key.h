// What a draw works out from the GL state alone (the fixed-function transform and texture
// snapshots, the array fetch plan and the arrays' bounds, a program's uniforms and draw state,
// the framebuffer object's views) is kept from one draw to the next while no call that may change
// state ran in between. A context counts such calls (every GL call but the array draws and
// glGetError) and what changes state outside them (each display-list command, make-current and
// release, a drawable change, a draw starting to render into textures, the resolution of rendered
// textures); a share group counts the calls of its members while it has more than one (they may
// change the objects another member draws with).
#pragma once
#include <cstdint>

namespace pineda {

struct StateKey {
  uint64_t context = 0, group = 0;  // (a context's count starts at 1: a default key matches none)
  bool operator==(const StateKey&) const = default;
};

}  // namespace pineda
