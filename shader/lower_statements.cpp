// Statements and function bodies, and the walk over a whole stage.
#include "shader/lowerer.h"

namespace pineda::shader::lowering {

void Lowerer::function_body(TIntermAggregate* def, bool main) {
  TIntermNode* body = def->getSequence().size() > 1 ? def->getSequence()[1] : nullptr;
  std::vector<TIntermSymbol*> locals;
  collect_locals(body, locals);
  for (TIntermSymbol* s : locals) {
    if (scopes_.back().count(s->getId())) continue;
    const VarType t = var_type(s->getType());
    const int base = alloc(t.size());
    scopes_.back()[s->getId()] = base;
    for (int c = 0; c < t.size(); ++c) emit_to(base + c, Op::Mov, k(0.0f), kNone, kNone, 0, 1);
  }
  int returns = 0;
  count_returns(body, returns);
  TIntermAggregate* seq = body ? body->getAsAggregate() : nullptr;
  TIntermBranch* tail = nullptr;
  if (seq && !seq->getSequence().empty()) {
    TIntermBranch* last = seq->getSequence().back()->getAsBranchNode();
    if (last && last->getFlowOp() == glslang::EOpReturn) tail = last;
  }
  // calls_ grows while the body lowers (nested calls): index it, never hold a reference.
  const size_t me = calls_.size() - 1;
  const bool frame = returns > (tail ? 1 : 0);
  calls_[me].frame = frame;
  if (frame) emit_control(Op::FuncBegin);
  if (seq && (seq->getOp() == glslang::EOpSequence || seq->getOp() == glslang::EOpScope)) {
    for (TIntermNode* n : seq->getSequence()) {
      if (n == tail) {
        if (tail->getExpression()) {
          Val v = rv(tail->getExpression());
          for (size_t i = 0; i < calls_[me].result.size(); ++i) emit_to(calls_[me].result[i], Op::Mov, v[i]);
        }
        continue;
      }
      stmt(n);
    }
  } else {
    stmt(body);
  }
  if (frame) emit_control(Op::FuncEnd);
  (void)main;
}

void Lowerer::stmt(TIntermNode* node) {
  if (!node) return;
  check_size();
  if (TIntermAggregate* a = node->getAsAggregate()) {
    switch (a->getOp()) {
      case glslang::EOpSequence: case glslang::EOpScope: case glslang::EOpNull:
        for (TIntermNode* n : a->getSequence()) stmt(n);
        return;
      case glslang::EOpLinkerObjects: case glslang::EOpFunction:
        return;
      default:
        rv(a);
        return;
    }
  }
  if (TIntermSelection* s = node->getAsSelectionNode()) {
    if (s->getBasicType() != glslang::EbtVoid) {
      rv(s);
      return;
    }
    Operand c = rv(s->getCondition())[0];
    emit_control(Op::IfBegin, c);
    stmt(s->getTrueBlock());
    if (s->getFalseBlock()) {
      emit_control(Op::Else);
      stmt(s->getFalseBlock());
    }
    emit_control(Op::EndIf);
    return;
  }
  if (TIntermLoop* l = node->getAsLoopNode()) {
    emit_control(Op::LoopBegin);
    if (l->testFirst() && l->getTest()) emit_control(Op::BreakIfNot, rv(l->getTest())[0]);
    stmt(l->getBody());
    emit_control(Op::ContinuePoint);
    if (l->getTerminal()) rv(l->getTerminal());
    if (!l->testFirst() && l->getTest()) emit_control(Op::BreakIfNot, rv(l->getTest())[0]);
    emit_control(Op::LoopEnd);
    return;
  }
  if (TIntermBranch* b = node->getAsBranchNode()) {
    switch (b->getFlowOp()) {
      case glslang::EOpKill:
        iface_.uses_discard = true;
        emit_control(Op::Discard);
        return;
      case glslang::EOpBreak: emit_control(Op::Break); return;
      case glslang::EOpContinue: emit_control(Op::Continue); return;
      case glslang::EOpReturn: {
        if (b->getExpression()) {
          Val v = rv(b->getExpression());
          const Val& result = calls_.back().result;
          for (size_t i = 0; i < result.size(); ++i) emit_to(result[i], Op::Mov, v[i]);
        }
        emit_control(Op::Return);
        return;
      }
      default:
        fail("error: unsupported branch\n");
    }
  }
  if (TIntermTyped* t = node->getAsTyped()) {
    rv(t);
    return;
  }
  fail("error: unsupported statement\n");
}

void Lowerer::run(const glslang::TIntermediate& tree) {
  TIntermAggregate* root = tree.getTreeRoot() ? tree.getTreeRoot()->getAsAggregate() : nullptr;
  if (!root) fail("error: empty shader\n");
  es_ = tree.getProfile() == EEsProfile;
  std::vector<TIntermNode*> globals;
  for (TIntermNode* n : root->getSequence()) {
    TIntermAggregate* a = n->getAsAggregate();
    if (a && a->getOp() == glslang::EOpFunction) {
      functions_[a->getName().c_str()] = a;
    } else if (a && a->getOp() == glslang::EOpLinkerObjects) {
      for (TIntermNode* o : a->getSequence())
        if (TIntermSymbol* s = o->getAsSymbolNode()) {
          if (s->getQualifier().storage == glslang::EvqVaryingOut)
            declared_outputs_[s->getName().c_str()] = var_type(s->getType(), s->getName().c_str());
          // A uniform with a GLSL 1.20 initializer is active even when unread (as Mesa): the
          // application may set it.
          if (s->getQualifier().storage == glslang::EvqUniform && !s->getConstArray().empty()) symbol_place(s);
        }
    } else {
      globals.push_back(n);
    }
  }
  auto main = functions_.find("main(");
  if (main == functions_.end()) fail("error: no main() function\n");
  scopes_.emplace_back();
  calls_.push_back(Call{});
  for (TIntermNode* n : globals) stmt(n);
  function_body(main->second, true);
  calls_.pop_back();
  scopes_.pop_back();
  route_outputs();
  code_.insts.insert(code_.insts.begin(), prologue_.begin(), prologue_.end());
}

}  // namespace pineda::shader::lowering
