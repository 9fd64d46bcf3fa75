// Where values live: variables in registers, uniforms, interface inputs and outputs;
// indexing, swizzles, loads and stores.
#include "shader/lowerer.h"

namespace pineda::shader::lowering {

Place whole(Place::Kind kind, int base, const VarType& type) {
  Place p;
  p.kind = kind;
  p.base = base;
  p.type = type;
  for (int i = 0; i < type.size(); ++i) p.comps.push_back(i);
  return p;
}

BuiltinAttribute builtin_attribute(const std::string& name) {
  if (name == "gl_Vertex") return BuiltinAttribute::Vertex;
  if (name == "gl_Normal") return BuiltinAttribute::Normal;
  if (name == "gl_Color") return BuiltinAttribute::Color;
  if (name == "gl_SecondaryColor") return BuiltinAttribute::SecondaryColor;
  if (name == "gl_FogCoord") return BuiltinAttribute::FogCoord;
  if (name.compare(0, 16, "gl_MultiTexCoord") == 0 && name.size() == 17 && name[16] >= '0' && name[16] <= '7')
    return static_cast<BuiltinAttribute>(static_cast<int>(BuiltinAttribute::MultiTexCoord0) + (name[16] - '0'));
  fail("error: unsupported built-in vertex input " + name + "\n");
}

int Lowerer::registers_for(std::unordered_map<long long, int>& map, TIntermSymbol* s, const VarType& t,
                           bool init) {
  auto it = map.find(s->getId());
  if (it != map.end()) return it->second;
  int base = alloc(t.size());
  map.emplace(s->getId(), base);
  if (init)
    for (int i = 0; i < t.size(); ++i) prologue(Op::Mov, base + i, 0, k(0.0f), 1);
  return base;
}

Val Lowerer::builtin_uniform(const std::string& name, const VarType& t) {
  std::string error;
  const UniformVar* u = iface_.uniform(name, t, true, error);
  if (!u) fail(error);
  return load(whole(Place::Uniform, u->offset, t));
}

Val Lowerer::builtin_attribute_value(const std::string& name) {
  auto it = interface_vars_.find(name);
  int base;
  if (it == interface_vars_.end()) {
    VarType t = VarType::vec(4);
    base = alloc(4);
    iface_.attributes.push_back(AttributeVar{name, t, iface_.input_slots, builtin_attribute(name)});
    for (int c = 0; c < 4; ++c) prologue(Op::LoadInput, base + c, iface_.input_slots * 4 + c);
    iface_.input_slots += 1;
    interface_vars_[name] = {t, base};
  } else {
    base = it->second.second;
  }
  return {base, base + 1, base + 2, base + 3};
}

Place Lowerer::symbol_place(TIntermSymbol* s) {
  const std::string name = s->getName().c_str();
  const auto storage = s->getQualifier().storage;
  // Constants (a 1.20 uniform's initializer also sits in the const array: it stays a uniform).
  if (storage == glslang::EvqConst || (storage != glslang::EvqUniform && !s->getConstArray().empty())) {
    VarType t = var_type(s->getType(), name);
    Place p;
    p.kind = Place::Values;
    p.type = t;
    p.comps = constant(s->getConstArray(), t.size());
    return p;
  }
  VarType t = var_type(s->getType(), name);
  switch (storage) {
    case glslang::EvqUniform: {
      std::string error;
      const UniformVar* u = iface_.uniform(name, t, starts_with_gl(name), error);
      if (!u) fail(error);
      const int offset = u->offset;
      if (!s->getConstArray().empty())
        for (UniformVar& var : iface_.uniforms)
          if (var.name == name && var.initial.empty()) {
            const glslang::TConstUnionArray& c = s->getConstArray();
            for (int i = 0; i < t.size() && i < c.size(); ++i) {
              const glslang::TConstUnion& v = c[i];
              var.initial.push_back(v.getType() == glslang::EbtBool ? (v.getBConst() ? 1.0f : 0.0f)
                                    : v.getType() == glslang::EbtInt ? static_cast<float>(v.getIConst())
                                    : v.getType() == glslang::EbtUint ? static_cast<float>(v.getUConst())
                                                                      : static_cast<float>(v.getDConst()));
            }
            var.initial.resize(t.size(), 0.0f);
          }
      return whole(Place::Uniform, offset, t);
    }
    case glslang::EvqTemporary: case glslang::EvqIn: case glslang::EvqOut: case glslang::EvqInOut:
    case glslang::EvqConstReadOnly: {
      for (auto it = scopes_.rbegin(); it != scopes_.rend(); ++it) {
        auto f = it->find(s->getId());
        if (f != it->end()) return whole(Place::Regs, f->second, t);
      }
      if (scopes_.empty()) fail("error: variable " + name + " used outside a function\n");
      return whole(Place::Regs, registers_for(scopes_.back(), s, t, true), t);
    }
    case glslang::EvqGlobal:
      return whole(Place::Regs, registers_for(globals_, s, t, true), t);
    default:
      break;
  }
  // Interface variables: one set of registers per name, loaded in the prologue (inputs) or
  // stored by the epilogue (outputs).
  auto it = interface_vars_.find(name);
  if (it != interface_vars_.end()) return whole(Place::Regs, it->second.second, it->second.first);
  int base = alloc(t.size());
  interface_vars_[name] = {t, base};
  const int n = t.size();
  switch (storage) {
    case glslang::EvqVaryingIn:
      if (stage_ == Stage::Vertex) {
        BuiltinAttribute b = starts_with_gl(name) ? builtin_attribute(name) : BuiltinAttribute::None;
        const int slots = t.cols * (t.array ? t.array : 1);
        iface_.attributes.push_back(AttributeVar{name, t, iface_.input_slots, b});
        for (int col = 0; col < slots; ++col)
          for (int c = 0; c < t.rows; ++c) prologue(Op::LoadInput, base + col * t.rows + c, (iface_.input_slots + col) * 4 + c);
        iface_.input_slots += slots;
      } else {
        if (t.is_struct()) fail("error: varying " + name + " of struct type\n");
        VaryingVar& v = iface_.add_varying(name, t);
        for (int c = 0; c < n; ++c) prologue(Op::LoadVarying, base + c, v.offset + c);
      }
      break;
    case glslang::EvqFace:
      iface_.reads.insert("gl_FrontFacing");
      prologue(Op::LoadFrontFacing, base);
      break;
    case glslang::EvqFragCoord:
      iface_.reads.insert("gl_FragCoord");
      for (int c = 0; c < 4; ++c) prologue(Op::LoadFragCoord, base + c, c);
      break;
    case glslang::EvqPointCoord:
      iface_.reads.insert("gl_PointCoord");
      for (int c = 0; c < 2; ++c) prologue(Op::LoadPointCoord, base + c, c);
      break;
    case glslang::EvqVaryingOut: case glslang::EvqPosition: case glslang::EvqPointSize:
    case glslang::EvqClipVertex: case glslang::EvqFragColor: case glslang::EvqFragDepth:
      outputs_.push_back(OutputVar{name, t, base});
      for (int c = 0; c < n; ++c) prologue(Op::Mov, base + c, 0, k(0.0f), 1);
      break;
    default:
      fail("error: unsupported variable " + name + "\n");
  }
  return whole(Place::Regs, base, t);
}

Place Lowerer::materialize(const Place& p) {
  Val v = load(p);
  int base = alloc(static_cast<int>(v.size()));
  for (size_t i = 0; i < v.size(); ++i) emit_to(base + static_cast<int>(i), Op::Mov, v[i]);
  return whole(Place::Regs, base, p.type);
}

Place Lowerer::place(TIntermTyped* node) {
  if (TIntermSymbol* s = node->getAsSymbolNode()) return symbol_place(s);
  TIntermBinary* b = node->getAsBinaryNode();
  if (b) {
    const TOperator op = b->getOp();
    if (op == glslang::EOpIndexDirect || op == glslang::EOpIndexIndirect ||
        op == glslang::EOpIndexDirectStruct || op == glslang::EOpVectorSwizzle) {
      Place p = place(b->getLeft());
      if (op == glslang::EOpVectorSwizzle) {
        Place q = p;
        q.comps.clear();
        for (TIntermNode* c : b->getRight()->getAsAggregate()->getSequence())
          q.comps.push_back(p.comps[c->getAsConstantUnion()->getConstArray()[0].getIConst()]);
        q.type = VarType::vec(static_cast<int>(q.comps.size()));
        q.type.base = p.type.base;
        return q;
      }
      if (op == glslang::EOpIndexDirectStruct) {
        const int m = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
        int off = 0;
        for (int i = 0; i < m; ++i) off += p.type.members[i].second.size();
        Place q = p;
        q.type = p.type.members[m].second;
        q.comps.assign(p.comps.begin() + off, p.comps.begin() + off + q.type.size());
        return q;
      }
      // Arrays, matrix columns, vector components.
      VarType elem;
      int count;
      if (p.type.array) {
        elem = p.type.element();
        count = p.type.array;
      } else if (p.type.cols > 1) {
        elem = VarType::vec(p.type.rows);
        count = p.type.cols;
      } else {
        elem = VarType::scalar(p.type.base);
        count = p.type.rows;
      }
      const int es = elem.size();
      TIntermSymbol* base_symbol = b->getLeft()->getAsSymbolNode();
      const bool frag_data = base_symbol && base_symbol->getName() == "gl_FragData";
      if (op == glslang::EOpIndexDirect) {
        int i = b->getRight()->getAsConstantUnion()->getConstArray()[0].getIConst();
        if (i < 0 || i >= count) fail("error: index out of range\n");
        if (frag_data) iface_.draw_buffers = std::max(iface_.draw_buffers, i + 1);
        Place q = p;
        q.type = elem;
        q.comps.assign(p.comps.begin() + i * es, p.comps.begin() + (i + 1) * es);
        return q;
      }
      if (frag_data) iface_.draw_buffers = kMaxDrawBuffers;
      Val index = rv(b->getRight());
      Place q = p;
      bool contiguous = q.kind != Place::Values;
      for (size_t i = 0; contiguous && i < q.comps.size(); ++i) contiguous = q.comps[i] == q.comps[0] + static_cast<int>(i);
      if (!contiguous && q.kind == Place::Regs && q.dyn == kNone && es == 1) {
        // A swizzle of a variable: stays assignable, one select per candidate component.
        Place c = q;
        c.choose_index = emit(Op::Clamp, index[0], k(0.0f), k(static_cast<float>(count - 1)));
        c.choose = q.comps;
        c.comps = {0};
        c.type = elem;
        return c;
      }
      if (!contiguous) q = materialize(q);
      Operand off = emit(Op::Clamp, index[0], k(0.0f), k(static_cast<float>(count - 1)));
      if (es != 1) off = emit(Op::Mul, off, k(static_cast<float>(es)));
      q.dyn = q.dyn == kNone ? off : emit(Op::Add, q.dyn, off);
      q.dyn_limit += (count - 1) * es;
      const int c0 = q.comps[0];
      q.comps.clear();
      for (int i = 0; i < es; ++i) q.comps.push_back(c0 + i);
      q.type = elem;
      return q;
    }
  }
  Place p;
  p.kind = Place::Values;
  p.type = var_type(node->getType());
  p.comps = rv(node);
  return p;
}

Val Lowerer::load(const Place& p) {
  if (p.choose_index != kNone) {
    Operand r = p.base + p.choose.back();
    for (int i = static_cast<int>(p.choose.size()) - 2; i >= 0; --i)
      r = emit(Op::Select, emit(Op::Eq, p.choose_index, k(static_cast<float>(i))), p.base + p.choose[i], r);
    return {r};
  }
  Val out;
  for (int c : p.comps) {
    switch (p.kind) {
      case Place::Values: out.push_back(c); break;
      case Place::Regs:
        out.push_back(p.dyn == kNone ? p.base + c : emit(Op::Gather, p.dyn, kNone, kNone, p.base + c, p.dyn_limit));
        break;
      case Place::Uniform:
        out.push_back(p.dyn == kNone ? emit(Op::LoadUniform, kNone, kNone, kNone, p.base + c)
                                     : emit(Op::GatherUniform, p.dyn, kNone, kNone, p.base + c, p.dyn_limit));
        break;
    }
  }
  return out;
}

void Lowerer::store(const Place& p, const Val& v0) {
  if (p.kind != Place::Regs) fail("error: assignment to a read-only value\n");
  if (p.choose_index != kNone) {
    Operand v = ir::is_const(v0[0]) ? v0[0] : emit(Op::Mov, v0[0]);
    for (size_t i = 0; i < p.choose.size(); ++i) {
      Operand target = p.base + p.choose[i];
      emit_to(target, Op::Select, emit(Op::Eq, p.choose_index, k(static_cast<float>(i))), v, target);
    }
    return;
  }
  // A source that is also a destination (v.xy = v.yx) is read before any write.
  Val v = v0;
  for (Operand& o : v)
    if (!ir::is_const(o)) {
      bool aliased = p.dyn != kNone ? (o >= p.base && o <= p.base + p.dyn_limit + p.type.size() + 64)
                                    : false;
      for (int c : p.comps) aliased = aliased || o == p.base + c;
      if (aliased) o = emit(Op::Mov, o);
    }
  for (size_t i = 0; i < p.comps.size(); ++i) {
    Operand src = at(v, i);
    if (p.dyn == kNone) emit_to(p.base + p.comps[i], Op::Mov, src);
    else code_.insts.push_back(ir::Inst{Op::Scatter, kNone, p.dyn, src, kNone, p.base + p.comps[i], p.dyn_limit});
  }
}

}  // namespace pineda::shader::lowering
