#include "shader/global_initializers.h"

#include <map>

namespace pineda::shader {
namespace {

// What a global's initializer is: its constant value, or "" when it is not a constant.
using Initializers = std::map<std::string, std::string>;

std::string constant_text(TIntermNode* value) {
  glslang::TIntermConstantUnion* c = value ? value->getAsConstantUnion() : nullptr;
  if (!c) return "";
  std::string text = "=";
  const glslang::TConstUnionArray& a = c->getConstArray();
  for (int i = 0; i < a.size(); ++i) text += std::to_string(a[i].getDConst()) + "," + std::to_string(a[i].getIConst()) + ";";
  return text;
}

// The globals a tree initializes: the assignments outside every function (glslang keeps the
// initializers of non-constant globals there; `const` ones are folded away).
void add_initialized(TIntermNode* node, Initializers& out) {
  if (!node) return;
  if (glslang::TIntermAggregate* a = node->getAsAggregate()) {
    if (a->getOp() == glslang::EOpSequence)
      for (TIntermNode* n : a->getSequence()) add_initialized(n, out);
    return;
  }
  glslang::TIntermBinary* b = node->getAsBinaryNode();
  if (!b || b->getOp() != glslang::EOpAssign) return;
  if (glslang::TIntermSymbol* s = b->getLeft()->getAsSymbolNode()) out[s->getName().c_str()] = constant_text(b->getRight());
}

}  // namespace

bool global_initializers_unique(const std::vector<const glslang::TIntermediate*>& units, std::string& log) {
  Initializers first;  // the first initializer seen of each global
  for (const glslang::TIntermediate* unit : units) {
    glslang::TIntermAggregate* root = unit && unit->getTreeRoot() ? unit->getTreeRoot()->getAsAggregate() : nullptr;
    if (!root) continue;
    Initializers here;
    for (TIntermNode* n : root->getSequence()) {
      glslang::TIntermAggregate* a = n->getAsAggregate();
      if (a && (a->getOp() == glslang::EOpFunction || a->getOp() == glslang::EOpLinkerObjects)) continue;
      add_initialized(n, here);
    }
    for (const auto& [name, value] : here) {
      auto [it, added] = first.emplace(name, value);
      if (added) continue;
      // Equal constant initializers are the same definition; anything else is two.
      if (value.empty() || it->second.empty()) {
        log += "error: global variable `" + name + "' has multiple initializers\n";
        return false;
      }
      if (value != it->second) {
        log += "error: initializers for global variable `" + name + "' have differing values\n";
        return false;
      }
    }
  }
  return true;
}

}  // namespace pineda::shader
