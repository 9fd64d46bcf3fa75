// GLSL's built-in functions: the table from glslang's operators to IR operations, and
// texture lookups.
#include "shader/lowerer.h"

#include <numbers>

namespace pineda::shader::lowering {

Val Lowerer::builtin_unary(TIntermUnary* u, const Val& a, const VarType& at_) {
  switch (u->getOp()) {
    case glslang::EOpRadians: return map2(Op::Mul, a, {k(static_cast<float>(std::numbers::pi / 180.0))});
    case glslang::EOpDegrees: return map2(Op::Mul, a, {k(static_cast<float>(180.0 / std::numbers::pi))});
    case glslang::EOpSin: return map1(Op::Sin, a);
    case glslang::EOpCos: return map1(Op::Cos, a);
    case glslang::EOpTan: return map1(Op::Tan, a);
    case glslang::EOpAsin: return map1(Op::Asin, a);
    case glslang::EOpAcos: return map1(Op::Acos, a);
    case glslang::EOpAtan: return map1(Op::Atan, a);
    case glslang::EOpExp: return map1(Op::Exp, a);
    case glslang::EOpLog: return map1(Op::Log, a);
    case glslang::EOpExp2: return map1(Op::Exp2, a);
    case glslang::EOpLog2: return map1(Op::Log2, a);
    case glslang::EOpSqrt: return map1(Op::Sqrt, a);
    case glslang::EOpInverseSqrt: return map1(Op::Rsq, a);
    case glslang::EOpAbs: return map1(Op::Abs, a);
    case glslang::EOpSign: return map1(Op::Sign, a);
    case glslang::EOpFloor: return map1(Op::Floor, a);
    case glslang::EOpCeil: return map1(Op::Ceil, a);
    case glslang::EOpFract: return map1(Op::Fract, a);
    case glslang::EOpLength: return {emit(Op::Sqrt, dot(a, a))};
    case glslang::EOpNormalize: {
      Operand s = emit(Op::NormScale, dot(a, a));
      return map2(Op::Mul, a, {s});
    }
    case glslang::EOpAny: return {reduce(Op::Or, a)};
    case glslang::EOpAll: return {reduce(Op::And, a)};
    case glslang::EOpDPdx: return map1(Op::Ddx, a);
    case glslang::EOpDPdy: return map1(Op::Ddy, a);
    case glslang::EOpFwidth: {
      Val x = map1(Op::Abs, map1(Op::Ddx, a));
      Val y = map1(Op::Abs, map1(Op::Ddy, a));
      return map2(Op::Add, x, y);
    }
    case glslang::EOpTranspose: {
      Val out;
      for (int j = 0; j < at_.rows; ++j)
        for (int i = 0; i < at_.cols; ++i) out.push_back(a[i * at_.rows + j]);
      return out;
    }
    case glslang::EOpNoise:
      // noise1..4 return 0 (documented in README.md), as several GL drivers do.
      return Val(var_type(u->getType()).size(), k(0.0f));
    default:
      fail("error: unsupported operation " + std::to_string(static_cast<int>(u->getOp())) + "\n");
  }
}

Val Lowerer::texture(TIntermAggregate* a) {
  const auto& seq = a->getSequence();
  TIntermTyped* sampler = seq[0]->getAsTyped();
  const VarType st = var_type(sampler->getType());
  const TOperator op = a->getOp();
  const bool proj = op == glslang::EOpTextureProj || op == glslang::EOpTextureProjLod;
  const bool lod = op == glslang::EOpTextureLod || op == glslang::EOpTextureProjLod;
  ir::TextureLookup t;
  switch (st.base) {
    case BaseType::Sampler1D: t.kind = SamplerKind::Tex1D; break;
    case BaseType::Sampler2D: t.kind = SamplerKind::Tex2D; break;
    case BaseType::Sampler3D: t.kind = SamplerKind::Tex3D; break;
    case BaseType::SamplerCube: t.kind = SamplerKind::Cube; break;
    case BaseType::Sampler1DShadow: t.kind = SamplerKind::Shadow1D; break;
    case BaseType::Sampler2DShadow: t.kind = SamplerKind::Shadow2D; break;
    case BaseType::Sampler2DRect: t.kind = SamplerKind::Rect; break;
    case BaseType::Sampler2DRectShadow: t.kind = SamplerKind::ShadowRect; break;
    default: fail("error: texture lookup without a sampler\n");
  }
  t.sampler = rv(sampler)[0];
  Val c = rv(seq[1]->getAsTyped());
  Val extra = seq.size() > 2 ? rv(seq[2]->getAsTyped()) : Val{};
  // Which coordinate components feed s, t, r (the shadow reference sits in r).
  int used[4] = {-1, -1, -1, -1};
  switch (t.kind) {
    case SamplerKind::Tex1D: used[0] = 0; break;
    case SamplerKind::Tex2D: case SamplerKind::Rect: used[0] = 0; used[1] = 1; break;
    case SamplerKind::Tex3D: case SamplerKind::Cube: case SamplerKind::Shadow2D: case SamplerKind::ShadowRect:
      used[0] = 0; used[1] = 1; used[2] = 2; break;
    case SamplerKind::Shadow1D: used[0] = 0; used[2] = 2; break;
  }
  Operand q = proj ? emit(Op::Div, k(1.0f), c.back()) : kNone;
  for (int i = 0; i < 4; ++i) {
    if (used[i] < 0) {
      t.coord[i] = k(0.0f);
      continue;
    }
    Operand v = c[used[i]];
    t.coord[i] = proj ? emit(Op::Mul, v, q) : v;
  }
  if (lod) {
    t.mode = LodMode::Explicit;
    t.lod = extra[0];
  } else if (stage_ == Stage::Vertex) {
    t.mode = LodMode::Explicit;
    t.lod = k(0.0f);
  } else if (!extra.empty()) {
    t.mode = LodMode::Bias;
    t.lod = extra[0];
  } else {
    t.mode = LodMode::Implicit;
  }
  Val out;
  for (int i = 0; i < 4; ++i) out.push_back(t.dst[i] = code_.new_register());
  code_.textures.push_back(t);
  code_.insts.push_back(ir::Inst{Op::Texture, kNone, kNone, kNone, kNone,
                                 static_cast<int>(code_.textures.size() - 1)});
  return out;
}

Val Lowerer::aggregate(TIntermAggregate* a) {
  const TOperator op = a->getOp();
  if (op == glslang::EOpFunctionCall) return call(a);
  if (op > glslang::EOpConstructGuardStart && op < glslang::EOpConstructGuardEnd) return construct(a);
  if (op == glslang::EOpTexture || op == glslang::EOpTextureProj || op == glslang::EOpTextureLod ||
      op == glslang::EOpTextureProjLod)
    return texture(a);
  if (op == glslang::EOpComma) {
    Val last;
    for (TIntermNode* n : a->getSequence()) last = rv(n->getAsTyped());
    return last;
  }
  if (op == glslang::EOpFtransform) {
    Val m = builtin_uniform("gl_ModelViewProjectionMatrix", VarType::mat(4, 4));
    Val v = builtin_attribute_value("gl_Vertex");
    return arith(glslang::EOpMatrixTimesVector, m, VarType::mat(4, 4), v, VarType::vec(4), VarType::vec(4));
  }
  std::vector<Val> args;
  std::vector<VarType> types;
  for (TIntermNode* n : a->getSequence()) {
    args.push_back(rv(n->getAsTyped()));
    types.push_back(var_type(n->getAsTyped()->getType()));
  }
  const VarType rt = var_type(a->getType());
  switch (op) {
    case glslang::EOpAtan: return map2(Op::Atan2, args[0], args[1]);
    case glslang::EOpPow: return map2(Op::Pow, args[0], args[1]);
    case glslang::EOpMod: return map2(Op::Mod, args[0], args[1]);
    case glslang::EOpMin: return map2(Op::Min, args[0], args[1]);
    case glslang::EOpMax: return map2(Op::Max, args[0], args[1]);
    case glslang::EOpClamp: return map3(Op::Clamp, args[0], args[1], args[2]);
    case glslang::EOpMix: return map3(Op::Mix, args[0], args[1], args[2]);
    case glslang::EOpStep: return map2(Op::Step, args[0], args[1]);
    case glslang::EOpSmoothStep: return map3(Op::Smoothstep, args[0], args[1], args[2]);
    case glslang::EOpDot: return {dot(args[0], args[1])};
    case glslang::EOpDistance: {
      Val d = map2(Op::Sub, args[0], args[1]);
      return {emit(Op::Sqrt, dot(d, d))};
    }
    case glslang::EOpCross: {
      const Val& x = args[0];
      const Val& y = args[1];
      Val out;
      for (int i = 0; i < 3; ++i) {
        int j = (i + 1) % 3, l = (i + 2) % 3;
        out.push_back(emit(Op::Sub, emit(Op::Mul, x[j], y[l]), emit(Op::Mul, x[l], y[j])));
      }
      return out;
    }
    case glslang::EOpFaceForward: {
      Operand d = dot(args[2], args[1]);
      Operand neg = emit(Op::Lt, d, k(0.0f));
      Val out;
      for (Operand n : args[0]) out.push_back(emit(Op::Select, neg, n, emit(Op::Neg, n)));
      return out;
    }
    case glslang::EOpReflect: {
      Operand d = emit(Op::Mul, dot(args[1], args[0]), k(2.0f));
      Val out;
      for (size_t i = 0; i < args[0].size(); ++i) out.push_back(emit(Op::Sub, args[0][i], emit(Op::Mul, d, args[1][i])));
      return out;
    }
    case glslang::EOpRefract: {
      const Val& I = args[0];
      const Val& N = args[1];
      Operand eta = args[2][0];
      Operand d = dot(N, I);
      // k = 1 - eta^2 (1 - d^2)
      Operand kk = emit(Op::Sub, k(1.0f), emit(Op::Mul, emit(Op::Mul, eta, eta), emit(Op::Sub, k(1.0f), emit(Op::Mul, d, d))));
      Operand ok = emit(Op::Ge, kk, k(0.0f));
      Operand f = emit(Op::Add, emit(Op::Mul, eta, d), emit(Op::Sqrt, emit(Op::Max, kk, k(0.0f))));
      Val out;
      for (size_t i = 0; i < I.size(); ++i)
        out.push_back(emit(Op::Select, ok, emit(Op::Sub, emit(Op::Mul, eta, I[i]), emit(Op::Mul, f, N[i])), k(0.0f)));
      return out;
    }
    case glslang::EOpMul: return map2(Op::Mul, args[0], args[1]);  // matrixCompMult
    case glslang::EOpOuterProduct: {
      Val out;
      for (size_t j = 0; j < args[1].size(); ++j)
        for (size_t i = 0; i < args[0].size(); ++i) out.push_back(emit(Op::Mul, args[0][i], args[1][j]));
      return out;
    }
    case glslang::EOpLessThan: return map2(Op::Lt, args[0], args[1]);
    case glslang::EOpLessThanEqual: return map2(Op::Le, args[0], args[1]);
    case glslang::EOpGreaterThan: return map2(Op::Gt, args[0], args[1]);
    case glslang::EOpGreaterThanEqual: return map2(Op::Ge, args[0], args[1]);
    case glslang::EOpVectorEqual: return map2(Op::Eq, args[0], args[1]);
    case glslang::EOpVectorNotEqual: return map2(Op::Ne, args[0], args[1]);
    case glslang::EOpNoise: return Val(rt.size(), k(0.0f));
    default:
      fail("error: unsupported built-in function " + std::to_string(static_cast<int>(op)) + "\n");
  }
}

}  // namespace pineda::shader::lowering
