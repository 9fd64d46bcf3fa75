#include "shader/tree_depth.h"

#include <utility>
#include <vector>

namespace pineda::shader {

int tree_depth(TIntermNode* root) {
  int deepest = 0;
  std::vector<std::pair<TIntermNode*, int>> pending;
  if (root) pending.emplace_back(root, 1);
  while (!pending.empty()) {
    const auto [node, depth] = pending.back();
    pending.pop_back();
    if (depth > deepest) deepest = depth;
    auto visit = [&, depth = depth](TIntermNode* child) {
      if (child) pending.emplace_back(child, depth + 1);
    };
    if (glslang::TIntermBinary* b = node->getAsBinaryNode()) {
      visit(b->getLeft());
      visit(b->getRight());
    } else if (glslang::TIntermUnary* u = node->getAsUnaryNode()) {
      visit(u->getOperand());
    } else if (glslang::TIntermAggregate* a = node->getAsAggregate()) {
      for (TIntermNode* c : a->getSequence()) visit(c);
    } else if (glslang::TIntermSelection* s = node->getAsSelectionNode()) {
      visit(s->getCondition());
      visit(s->getTrueBlock());
      visit(s->getFalseBlock());
    } else if (glslang::TIntermLoop* l = node->getAsLoopNode()) {
      visit(l->getTest());
      visit(l->getBody());
      visit(l->getTerminal());
    } else if (glslang::TIntermBranch* br = node->getAsBranchNode()) {
      visit(br->getExpression());
    } else if (glslang::TIntermSwitch* sw = node->getAsSwitchNode()) {
      visit(sw->getCondition());
      visit(sw->getBody());
    }
  }
  return deepest;
}

}  // namespace pineda::shader
