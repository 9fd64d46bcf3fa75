// Questions about glslang's tree that the lowering asks before emitting anything.
#include "shader/lowerer.h"

namespace pineda::shader::lowering {

bool is_assign(TOperator op) {
  switch (op) {
    case glslang::EOpAssign: case glslang::EOpAddAssign: case glslang::EOpSubAssign:
    case glslang::EOpMulAssign: case glslang::EOpDivAssign: case glslang::EOpVectorTimesScalarAssign:
    case glslang::EOpMatrixTimesScalarAssign: case glslang::EOpVectorTimesMatrixAssign:
    case glslang::EOpMatrixTimesMatrixAssign:
      return true;
    default:
      return false;
  }
}

bool has_side_effects(TIntermNode* node) {
  if (!node) return false;
  if (TIntermBinary* b = node->getAsBinaryNode())
    return is_assign(b->getOp()) || has_side_effects(b->getLeft()) || has_side_effects(b->getRight());
  if (TIntermUnary* u = node->getAsUnaryNode()) {
    switch (u->getOp()) {
      case glslang::EOpPostIncrement: case glslang::EOpPostDecrement:
      case glslang::EOpPreIncrement: case glslang::EOpPreDecrement:
        return true;
      default:
        return has_side_effects(u->getOperand());
    }
  }
  if (TIntermAggregate* a = node->getAsAggregate()) {
    if (a->getOp() == glslang::EOpFunctionCall) return true;
    for (TIntermNode* c : a->getSequence())
      if (has_side_effects(c)) return true;
    return false;
  }
  if (TIntermSelection* s = node->getAsSelectionNode())
    return has_side_effects(s->getCondition()) || has_side_effects(s->getTrueBlock()) ||
           has_side_effects(s->getFalseBlock());
  return false;
}

TOperator base_of_assign(TOperator op) {
  switch (op) {
    case glslang::EOpAddAssign: return glslang::EOpAdd;
    case glslang::EOpSubAssign: return glslang::EOpSub;
    case glslang::EOpMulAssign: return glslang::EOpMul;
    case glslang::EOpDivAssign: return glslang::EOpDiv;
    case glslang::EOpVectorTimesScalarAssign: return glslang::EOpVectorTimesScalar;
    case glslang::EOpMatrixTimesScalarAssign: return glslang::EOpMatrixTimesScalar;
    case glslang::EOpVectorTimesMatrixAssign: return glslang::EOpVectorTimesMatrix;
    case glslang::EOpMatrixTimesMatrixAssign: return glslang::EOpMatrixTimesMatrix;
    default: return glslang::EOpNull;
  }
}

void count_returns(TIntermNode* node, int& count) {
  if (!node) return;
  if (TIntermBranch* b = node->getAsBranchNode()) {
    if (b->getFlowOp() == glslang::EOpReturn) ++count;
    return;
  }
  if (TIntermAggregate* a = node->getAsAggregate()) {
    for (TIntermNode* c : a->getSequence()) count_returns(c, count);
  } else if (TIntermSelection* s = node->getAsSelectionNode()) {
    count_returns(s->getTrueBlock(), count);
    count_returns(s->getFalseBlock(), count);
  } else if (TIntermLoop* l = node->getAsLoopNode()) {
    count_returns(l->getBody(), count);
  }
}

void collect_locals(TIntermNode* node, std::vector<TIntermSymbol*>& out) {
  if (!node) return;
  if (TIntermSymbol* s = node->getAsSymbolNode()) {
    if (s->getQualifier().storage == glslang::EvqTemporary) out.push_back(s);
  } else if (TIntermBinary* b = node->getAsBinaryNode()) {
    collect_locals(b->getLeft(), out);
    collect_locals(b->getRight(), out);
  } else if (TIntermUnary* u = node->getAsUnaryNode()) {
    collect_locals(u->getOperand(), out);
  } else if (TIntermAggregate* a = node->getAsAggregate()) {
    for (TIntermNode* c : a->getSequence()) collect_locals(c, out);
  } else if (TIntermSelection* s = node->getAsSelectionNode()) {
    collect_locals(s->getCondition(), out);
    collect_locals(s->getTrueBlock(), out);
    collect_locals(s->getFalseBlock(), out);
  } else if (TIntermLoop* l = node->getAsLoopNode()) {
    collect_locals(l->getTest(), out);
    collect_locals(l->getBody(), out);
    collect_locals(l->getTerminal(), out);
  } else if (TIntermBranch* br = node->getAsBranchNode()) {
    collect_locals(br->getExpression(), out);
  }
}

}  // namespace pineda::shader::lowering
