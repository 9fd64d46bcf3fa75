// The nesting depth of a glslang tree, measured without recursion: the lowering recurses once
// per level, so the front end refuses trees deeper than kMaxTreeDepth before it runs.
#pragma once
#include <glslang/MachineIndependent/localintermediate.h>

namespace pineda::shader {

// Far above real shaders (tens of levels); `a + a + ... + a` of 1000 terms is 1000 levels.
// What keeps the lowering's stack use, even under AddressSanitizer, within a thread's 8 MB.
constexpr int kMaxTreeDepth = 1024;

// The number of nodes on the longest path from `root` down to a leaf (0 for no tree).
int tree_depth(TIntermNode* root);

}  // namespace pineda::shader
