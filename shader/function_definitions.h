// The function definitions of a glslang tree: the EOpFunction nodes at its top.
#pragma once
#include <glslang/MachineIndependent/localintermediate.h>

#include <vector>

namespace pineda::shader {

inline std::vector<glslang::TIntermAggregate*> function_definitions(TIntermNode* root) {
  std::vector<glslang::TIntermAggregate*> out;
  glslang::TIntermAggregate* top = root ? root->getAsAggregate() : nullptr;
  if (!top) return out;
  for (TIntermNode* n : top->getSequence())
    if (glslang::TIntermAggregate* f = n ? n->getAsAggregate() : nullptr; f && f->getOp() == glslang::EOpFunction)
      out.push_back(f);
  return out;
}

}  // namespace pineda::shader
