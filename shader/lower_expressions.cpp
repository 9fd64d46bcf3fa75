// Expressions: constants, operators, constructors, ?:, and inlined calls of user functions.
#include "shader/lowerer.h"

namespace pineda::shader::lowering {

Val Lowerer::constant(const glslang::TConstUnionArray& a, int n) {
  Val out;
  for (int i = 0; i < n && i < a.size(); ++i) {
    const glslang::TConstUnion& c = a[i];
    float v = 0.0f;
    switch (c.getType()) {
      case glslang::EbtFloat: case glslang::EbtDouble: v = static_cast<float>(c.getDConst()); break;
      case glslang::EbtInt: v = static_cast<float>(c.getIConst()); break;
      case glslang::EbtUint: v = static_cast<float>(c.getUConst()); break;
      case glslang::EbtBool: v = c.getBConst() ? 1.0f : 0.0f; break;
      default: break;
    }
    out.push_back(k(v));
  }
  while (static_cast<int>(out.size()) < n) out.push_back(k(0.0f));
  return out;
}

Val Lowerer::rv(TIntermTyped* node) {
  check_size();
  if (expression_depth_ >= kMaxExpressionDepth)
    fail("error: expressions nested too deeply (more than " + std::to_string(kMaxExpressionDepth) +
         " levels, through inlined calls)\n");
  struct Nested {
    int& depth;
    explicit Nested(int& d) : depth(++d) {}
    ~Nested() { --depth; }
  } nested(expression_depth_);
  if (TIntermConstantUnion* c = node->getAsConstantUnion())
    return constant(c->getConstArray(), var_type(node->getType()).size());
  if (TIntermSymbol* s = node->getAsSymbolNode()) return load(symbol_place(s));
  if (TIntermBinary* b = node->getAsBinaryNode()) return binary(b);
  if (TIntermUnary* u = node->getAsUnaryNode()) return unary(u);
  if (TIntermAggregate* a = node->getAsAggregate()) return aggregate(a);
  if (TIntermSelection* s = node->getAsSelectionNode()) return select(s);
  fail("error: unsupported expression\n");
}

Val Lowerer::arith(TOperator op, const Val& a, const VarType& at_, const Val& b, const VarType& bt,
                   const VarType& rt) {
  switch (op) {
    case glslang::EOpAdd: return map2(Op::Add, a, b);
    case glslang::EOpSub: return map2(Op::Sub, a, b);
    case glslang::EOpMul: case glslang::EOpVectorTimesScalar: case glslang::EOpMatrixTimesScalar:
      return map2(Op::Mul, a, b);
    case glslang::EOpDiv: {
      Val q = map2(Op::Div, a, b);
      return rt.base == BaseType::Int ? map1(Op::Trunc, q) : q;
    }
    case glslang::EOpMatrixTimesVector: {
      const int r = at_.rows, c = at_.cols;
      Val out;
      for (int i = 0; i < r; ++i) {
        Operand sum = emit(Op::Mul, a[i], b[0]);
        for (int j = 1; j < c; ++j) sum = emit(Op::Mad, a[j * r + i], b[j], sum);
        out.push_back(sum);
      }
      return out;
    }
    case glslang::EOpVectorTimesMatrix: {
      const int r = bt.rows, c = bt.cols;
      Val out;
      for (int j = 0; j < c; ++j) out.push_back(dot(a, Val(b.begin() + j * r, b.begin() + (j + 1) * r)));
      return out;
    }
    case glslang::EOpMatrixTimesMatrix: {
      const int r = at_.rows, kk = at_.cols, c = bt.cols;
      Val out;
      for (int j = 0; j < c; ++j)
        for (int i = 0; i < r; ++i) {
          Operand sum = emit(Op::Mul, a[i], b[j * kk]);
          for (int t = 1; t < kk; ++t) sum = emit(Op::Mad, a[t * r + i], b[j * kk + t], sum);
          out.push_back(sum);
        }
      return out;
    }
    default:
      fail("error: unsupported operator\n");
  }
}

Val Lowerer::logical(TIntermBinary* b) {
  const bool is_and = b->getOp() == glslang::EOpLogicalAnd;
  Val l = rv(b->getLeft());
  if (!has_side_effects(b->getRight())) return {emit(is_and ? Op::And : Op::Or, l[0], rv(b->getRight())[0])};
  Operand r = emit(Op::Mov, l[0]);
  emit_control(Op::IfBegin, is_and ? r : emit(Op::Not, r));
  Val rr = rv(b->getRight());
  emit_to(r, Op::Mov, rr[0]);
  emit_control(Op::EndIf);
  return {r};
}

Val Lowerer::binary(TIntermBinary* b) {
  const TOperator op = b->getOp();
  switch (op) {
    case glslang::EOpIndexDirect: case glslang::EOpIndexIndirect: case glslang::EOpIndexDirectStruct:
    case glslang::EOpVectorSwizzle:
      return load(place(b));
    case glslang::EOpAssign: {
      Place p = place(b->getLeft());
      Val v = rv(b->getRight());
      store(p, v);
      return v;
    }
    case glslang::EOpComma:
      rv(b->getLeft());
      return rv(b->getRight());
    case glslang::EOpLogicalAnd: case glslang::EOpLogicalOr:
      return logical(b);
    default:
      break;
  }
  if (is_assign(op)) {
    Place p = place(b->getLeft());
    Val cur = load(p);
    if (has_side_effects(b->getRight())) cur = copy(cur);
    Val r = rv(b->getRight());
    Val v = arith(base_of_assign(op), cur, p.type, r, var_type(b->getRight()->getType()), p.type);
    store(p, v);
    return v;
  }
  Val l = rv(b->getLeft());
  if (has_side_effects(b->getRight())) l = copy(l);
  Val r = rv(b->getRight());
  switch (op) {
    case glslang::EOpLogicalXor: return {emit(Op::Xor, l[0], r[0])};
    case glslang::EOpEqual: case glslang::EOpNotEqual: {
      Operand all = reduce(Op::And, map2(Op::Eq, l, r));
      return {op == glslang::EOpEqual ? all : emit(Op::Not, all)};
    }
    case glslang::EOpLessThan: return map2(Op::Lt, l, r);
    case glslang::EOpGreaterThan: return map2(Op::Gt, l, r);
    case glslang::EOpLessThanEqual: return map2(Op::Le, l, r);
    case glslang::EOpGreaterThanEqual: return map2(Op::Ge, l, r);
    case glslang::EOpVectorEqual: return map2(Op::Eq, l, r);
    case glslang::EOpVectorNotEqual: return map2(Op::Ne, l, r);
    default:
      return arith(op, l, var_type(b->getLeft()->getType()), r, var_type(b->getRight()->getType()),
                   var_type(b->getType()));
  }
}

Val Lowerer::unary(TIntermUnary* u) {
  const TOperator op = u->getOp();
  switch (op) {
    case glslang::EOpPostIncrement: case glslang::EOpPostDecrement: case glslang::EOpPreIncrement:
    case glslang::EOpPreDecrement: {
      Place p = place(u->getOperand());
      Val old = copy(load(p));
      const bool inc = op == glslang::EOpPostIncrement || op == glslang::EOpPreIncrement;
      Val now = map2(inc ? Op::Add : Op::Sub, old, {k(1.0f)});
      store(p, now);
      return (op == glslang::EOpPostIncrement || op == glslang::EOpPostDecrement) ? old : now;
    }
    default:
      break;
  }
  Val a = rv(u->getOperand());
  const VarType at_ = var_type(u->getOperand()->getType());
  switch (op) {
    case glslang::EOpNegative: return map1(Op::Neg, a);
    case glslang::EOpLogicalNot: case glslang::EOpVectorLogicalNot: return map1(Op::Not, a);
    case glslang::EOpCopyObject: case glslang::EOpConvIntToFloat: case glslang::EOpConvBoolToFloat:
    case glslang::EOpConvBoolToInt: case glslang::EOpConvUintToFloat: case glslang::EOpConvIntToUint:
    case glslang::EOpConvUintToInt:
      return a;
    case glslang::EOpConvFloatToInt: case glslang::EOpConvFloatToUint: return map1(Op::Trunc, a);
    case glslang::EOpConvIntToBool: case glslang::EOpConvFloatToBool: case glslang::EOpConvUintToBool:
      return map1(Op::ToBool, a);
    default:
      return builtin_unary(u, a, at_);
  }
}

Val Lowerer::construct(TIntermAggregate* a) {
  const VarType rt = var_type(a->getType());
  const int n = rt.size();
  std::vector<Val> args;
  std::vector<VarType> types;
  const auto& seq = a->getSequence();
  for (size_t i = 0; i < seq.size(); ++i) {
    TIntermTyped* t = seq[i]->getAsTyped();
    Val v = rv(t);
    bool later_effects = false;
    for (size_t j = i + 1; j < seq.size(); ++j) later_effects = later_effects || has_side_effects(seq[j]);
    args.push_back(later_effects ? copy(v) : v);
    types.push_back(var_type(t->getType()));
  }
  auto convert = [&](Operand o, BaseType from) -> Operand {
    if (rt.is_struct() || rt.base == from) return o;
    if (rt.base == BaseType::Int && from == BaseType::Float) return emit(Op::Trunc, o);
    if (rt.base == BaseType::Bool) return emit(Op::ToBool, o);
    return o;
  };
  Val out;
  if (rt.is_matrix() && args.size() == 1 && types[0].size() == 1) {
    Operand s = convert(args[0][0], types[0].base);
    for (int j = 0; j < rt.cols; ++j)
      for (int i = 0; i < rt.rows; ++i) out.push_back(i == j ? s : k(0.0f));
    return out;
  }
  if (rt.is_matrix() && args.size() == 1 && types[0].is_matrix()) {
    const VarType& m = types[0];
    for (int j = 0; j < rt.cols; ++j)
      for (int i = 0; i < rt.rows; ++i)
        out.push_back(j < m.cols && i < m.rows ? args[0][j * m.rows + i] : k(i == j ? 1.0f : 0.0f));
    return out;
  }
  if (args.size() == 1 && types[0].size() == 1 && !rt.is_struct() && rt.array == 0) {
    Operand s = convert(args[0][0], types[0].base);
    return Val(n, s);
  }
  for (size_t i = 0; i < args.size() && static_cast<int>(out.size()) < n; ++i)
    for (Operand o : args[i]) {
      if (static_cast<int>(out.size()) == n) break;
      out.push_back(convert(o, types[i].base));
    }
  while (static_cast<int>(out.size()) < n) out.push_back(k(0.0f));
  return out;
}

Val Lowerer::select(TIntermSelection* s) {
  const VarType rt = var_type(s->getType());
  Operand c = rv(s->getCondition())[0];
  TIntermTyped* t = s->getTrueBlock()->getAsTyped();
  TIntermTyped* f = s->getFalseBlock()->getAsTyped();
  if (!has_side_effects(t) && !has_side_effects(f)) {
    Val a = rv(t);
    Val b = rv(f);
    Val out;
    for (size_t i = 0; i < a.size(); ++i) out.push_back(emit(Op::Select, c, a[i], b[i]));
    return out;
  }
  const int n = rt.size();
  int base = alloc(n);
  emit_control(Op::IfBegin, c);
  Val a = rv(t);
  for (int i = 0; i < n; ++i) emit_to(base + i, Op::Mov, a[i]);
  emit_control(Op::Else);
  Val b = rv(f);
  for (int i = 0; i < n; ++i) emit_to(base + i, Op::Mov, b[i]);
  emit_control(Op::EndIf);
  Val out;
  for (int i = 0; i < n; ++i) out.push_back(base + i);
  return out;
}

Val Lowerer::call(TIntermAggregate* a) {
  auto it = functions_.find(a->getName().c_str());
  if (it == functions_.end()) fail(std::string("error: no definition of function ") + a->getName().c_str() + "\n");
  if (calls_.size() >= kMaxInlineDepth) fail("error: function calls nested too deeply (recursion?)\n");
  TIntermAggregate* def = it->second;
  const auto& params = def->getSequence()[0]->getAsAggregate()->getSequence();
  const auto& args = a->getSequence();
  std::unordered_map<long long, int> scope;
  std::vector<std::pair<Place, int>> copy_out;  // caller place, parameter registers
  for (size_t i = 0; i < params.size() && i < args.size(); ++i) {
    TIntermSymbol* p = params[i]->getAsSymbolNode();
    const VarType t = var_type(p->getType());
    const int base = alloc(t.size());
    scope[p->getId()] = base;
    const auto q = p->getQualifier().storage;
    TIntermTyped* arg = args[i]->getAsTyped();
    if (q == glslang::EvqOut || q == glslang::EvqInOut) {
      Place where = place(arg);
      if (q == glslang::EvqInOut) {
        Val v = load(where);
        for (int c = 0; c < t.size(); ++c) emit_to(base + c, Op::Mov, v[c]);
      } else {
        for (int c = 0; c < t.size(); ++c) emit_to(base + c, Op::Mov, k(0.0f), kNone, kNone, 0, 1);
      }
      copy_out.emplace_back(where, base);
    } else {
      Val v = rv(arg);
      for (int c = 0; c < t.size(); ++c) emit_to(base + c, Op::Mov, v[c]);
    }
  }
  scopes_.push_back(std::move(scope));
  Call ctx;
  if (def->getType().getBasicType() != glslang::EbtVoid) {
    const VarType rt = var_type(def->getType());
    const int base = alloc(rt.size());
    for (int c = 0; c < rt.size(); ++c) ctx.result.push_back(base + c);
  }
  calls_.push_back(ctx);
  function_body(def, false);
  calls_.pop_back();
  scopes_.pop_back();
  for (auto& [where, base] : copy_out) {
    Val v;
    for (int c = 0; c < where.type.size(); ++c) v.push_back(base + c);
    store(where, v);
  }
  return ctx.result;
}

}  // namespace pineda::shader::lowering
