// Lowering of glslang's typed tree to the IR: every value becomes one operand per scalar
// component, user functions are inlined at each call, control flow becomes the structured
// marker operations that the executor runs with lane masks.
#include "shader/lower.h"

#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include <cmath>
#include <map>
#include <numbers>
#include <unordered_map>

namespace pineda::shader {

namespace {

using glslang::TIntermAggregate;
using glslang::TIntermBinary;
using glslang::TIntermBranch;
using glslang::TIntermConstantUnion;
using glslang::TIntermLoop;
using ::TIntermNode;
using glslang::TIntermSelection;
using glslang::TIntermSymbol;
using glslang::TIntermTyped;
using glslang::TIntermUnary;
using glslang::TOperator;
using glslang::TType;
using ir::kNone;
using ir::Op;
using ir::Operand;
using Val = std::vector<Operand>;

struct LowerError {
  std::string message;
};
[[noreturn]] void fail(const std::string& message) { throw LowerError{message}; }

constexpr int kMaxTextureCoords = 8;
constexpr int kMaxInlineDepth = 64;
// Bounds on what one stage may lower to, so that huge arrays or an explosion of inlined
// calls end in a link error rather than exhausting memory.
constexpr int kMaxInstructions = 1 << 18;
constexpr int kMaxRegisters = 1 << 18;
// Expressions nested in expressions, through inlined calls too: rv() recurses once per level
// (several kB of stack each under AddressSanitizer).
constexpr int kMaxExpressionDepth = 512;

bool starts_with_gl(const std::string& name) { return name.compare(0, 3, "gl_") == 0; }

VarType var_type(const TType& t, const std::string& name = {});

VarType var_type_of_element(const TType& t) {
  VarType v;
  if (t.isStruct()) {
    for (const glslang::TTypeLoc& m : *t.getStruct())
      v.members.emplace_back(m.type->getFieldName().c_str(), var_type(*m.type));
    return v;
  }
  switch (t.getBasicType()) {
    case glslang::EbtFloat: case glslang::EbtDouble: v.base = BaseType::Float; break;
    case glslang::EbtInt: case glslang::EbtUint: v.base = BaseType::Int; break;
    case glslang::EbtBool: v.base = BaseType::Bool; break;
    case glslang::EbtSampler: {
      const glslang::TSampler& s = t.getSampler();
      switch (s.dim) {
        case glslang::Esd1D: v.base = s.shadow ? BaseType::Sampler1DShadow : BaseType::Sampler1D; break;
        case glslang::Esd2D: v.base = s.shadow ? BaseType::Sampler2DShadow : BaseType::Sampler2D; break;
        case glslang::Esd3D: v.base = BaseType::Sampler3D; break;
        case glslang::EsdCube: v.base = BaseType::SamplerCube; break;
        default: fail("error: unsupported sampler type\n");
      }
      break;
    }
    default: fail("error: unsupported type\n");
  }
  if (t.isMatrix()) {
    v.cols = t.getMatrixCols();
    v.rows = t.getMatrixRows();
  } else {
    v.rows = t.getVectorSize();
  }
  return v;
}

VarType var_type(const TType& t, const std::string& name) {
  VarType v = var_type_of_element(t);
  if (t.isArray()) {
    // An unsized array (gl_TexCoord used with constant indices) has the size its highest
    // index implies.
    int n = t.isSizedArray() ? t.getOuterArraySize() : t.getImplicitArraySize();
    v.array = n < 1 ? 1 : (n > kMaxTextureCoords && name == "gl_TexCoord" ? kMaxTextureCoords : n);
  }
  return v;
}

// Where a value lives: registers (variables), the uniform store, or plain operands (an
// expression's result). `comps` are offsets from `base` (registers, uniforms) or operands
// (values); `dyn`, when set, is a per-lane offset (an integral float in 0..dyn_limit)
// added to every component.
struct Place {
  enum Kind { Regs, Uniform, Values } kind = Values;
  int base = 0;
  std::vector<int> comps;
  Operand dyn = kNone;
  int dyn_limit = 0;
  // A swizzled vector indexed dynamically (v.wzyx[i]): component `choose[k]` when the index is
  // k; comps is unused.
  Operand choose_index = kNone;
  std::vector<int> choose;
  VarType type;
};

Place whole(Place::Kind kind, int base, const VarType& type) {
  Place p;
  p.kind = kind;
  p.base = base;
  p.type = type;
  for (int i = 0; i < type.size(); ++i) p.comps.push_back(i);
  return p;
}

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

// Return statements of a function body, and whether the last statement is one.
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

class Lowerer {
 public:
  Lowerer(Stage stage, Interface& iface, ir::Code& code) : stage_(stage), iface_(iface), code_(code) {}

  void run(const glslang::TIntermediate& tree);

 private:
  struct Call {
    Val result;
    bool frame = false;
  };
  struct OutputVar {
    std::string name;
    VarType type;
    int reg;
  };

  // --- emission ---
  Operand emit(Op op, Operand a = kNone, Operand b = kNone, Operand c = kNone, int i0 = 0, int i1 = 0) {
    Operand d = code_.new_register();
    code_.insts.push_back(ir::Inst{op, d, a, b, c, i0, i1});
    return d;
  }
  void emit_to(Operand d, Op op, Operand a = kNone, Operand b = kNone, Operand c = kNone, int i0 = 0,
               int i1 = 0) {
    code_.insts.push_back(ir::Inst{op, d, a, b, c, i0, i1});
  }
  void emit_control(Op op, Operand a = kNone) { code_.insts.push_back(ir::Inst{op, kNone, a}); }
  void prologue(Op op, Operand d, int i0 = 0, Operand a = kNone, int i1 = 0) {
    prologue_.push_back(ir::Inst{op, d, a, kNone, kNone, i0, i1});
  }
  Operand k(float v) { return code_.constant(v); }
  int alloc(int n) {
    if (n < 0 || code_.registers > kMaxRegisters - n) fail("error: shader too large (too many values)\n");
    return code_.new_registers(n);
  }
  void check_size() const {
    if (code_.insts.size() + prologue_.size() > static_cast<size_t>(kMaxInstructions))
      fail("error: shader too large (too many instructions after inlining)\n");
  }
  Val copy(const Val& v) {
    Val out;
    for (Operand o : v) out.push_back(ir::is_const(o) ? o : emit(Op::Mov, o));
    return out;
  }
  Val map1(Op op, const Val& a) {
    Val out;
    for (Operand o : a) out.push_back(emit(op, o));
    return out;
  }
  static Operand at(const Val& v, size_t i) { return v.size() == 1 ? v[0] : v[i]; }
  Val map2(Op op, const Val& a, const Val& b) {
    size_t n = std::max(a.size(), b.size());
    Val out;
    for (size_t i = 0; i < n; ++i) out.push_back(emit(op, at(a, i), at(b, i)));
    return out;
  }
  Val map3(Op op, const Val& a, const Val& b, const Val& c) {
    size_t n = std::max({a.size(), b.size(), c.size()});
    Val out;
    for (size_t i = 0; i < n; ++i) out.push_back(emit(op, at(a, i), at(b, i), at(c, i)));
    return out;
  }
  Operand dot(const Val& a, const Val& b) {
    Operand sum = emit(Op::Mul, a[0], b[0]);
    for (size_t i = 1; i < a.size(); ++i) sum = emit(Op::Mad, a[i], b[i], sum);
    return sum;
  }
  Operand reduce(Op op, const Val& v) {
    Operand r = v[0];
    for (size_t i = 1; i < v.size(); ++i) r = emit(op, r, v[i]);
    return r;
  }

  // --- places ---
  Place symbol_place(TIntermSymbol* s);
  Place place(TIntermTyped* node);
  Val load(const Place& p);
  void store(const Place& p, const Val& v);
  Place materialize(const Place& p);
  int registers_for(std::unordered_map<long long, int>& map, TIntermSymbol* s, const VarType& t, bool init);

  // --- expressions ---
  Val rv(TIntermTyped* node);
  Val constant(const glslang::TConstUnionArray& a, int n);
  Val binary(TIntermBinary* b);
  Val unary(TIntermUnary* u);
  Val aggregate(TIntermAggregate* a);
  Val arith(TOperator op, const Val& a, const VarType& at, const Val& b, const VarType& bt, const VarType& rt);
  Val construct(TIntermAggregate* a);
  Val call(TIntermAggregate* a);
  Val texture(TIntermAggregate* a);
  Val select(TIntermSelection* s);
  Val logical(TIntermBinary* b);
  Val builtin_uniform(const std::string& name, const VarType& t);
  Val builtin_attribute_value(const std::string& name);

  // --- statements ---
  void stmt(TIntermNode* node);
  void function_body(TIntermAggregate* def, bool main);

  void route_outputs();

  Stage stage_;
  Interface& iface_;
  ir::Code& code_;
  std::vector<ir::Inst> prologue_;
  std::map<std::string, TIntermAggregate*> functions_;
  std::unordered_map<long long, int> globals_;
  std::vector<std::unordered_map<long long, int>> scopes_;
  std::vector<Call> calls_;
  int expression_depth_ = 0;
  std::vector<OutputVar> outputs_;
  std::map<std::string, std::pair<VarType, int>> interface_vars_;  // inputs / outputs by name
  std::map<std::string, VarType> declared_outputs_;
};

// ---------------------------------------------------------------------------------------

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
      fail("error: unsupported operation " + std::to_string(static_cast<int>(op)) + "\n");
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
    default: fail("error: texture lookup without a sampler\n");
  }
  t.sampler = rv(sampler)[0];
  Val c = rv(seq[1]->getAsTyped());
  Val extra = seq.size() > 2 ? rv(seq[2]->getAsTyped()) : Val{};
  // Which coordinate components feed s, t, r (the shadow reference sits in r).
  int used[4] = {-1, -1, -1, -1};
  switch (t.kind) {
    case SamplerKind::Tex1D: used[0] = 0; break;
    case SamplerKind::Tex2D: used[0] = 0; used[1] = 1; break;
    case SamplerKind::Tex3D: case SamplerKind::Cube: case SamplerKind::Shadow2D:
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

// The epilogue: vertex outputs to their output floats (varyings by name, the built-in
// colours to the fragment inputs they feed), fragment outputs to the block.
void Lowerer::route_outputs() {
  if (stage_ == Stage::Fragment) {
    for (const OutputVar& o : outputs_) {
      if (o.name == "gl_FragColor") {
        iface_.draw_buffers = std::max(iface_.draw_buffers, 1);
        for (int c = 0; c < 4; ++c)
          code_.insts.push_back(ir::Inst{Op::StoreColor, kNone, o.reg + c, kNone, kNone, c, 1});
      } else if (o.name == "gl_FragData") {
        for (int b = 0; b < iface_.draw_buffers && b < o.type.array; ++b)
          for (int c = 0; c < 4; ++c)
            code_.insts.push_back(ir::Inst{Op::StoreColor, kNone, o.reg + b * 4 + c, kNone, kNone, b * 4 + c, 0});
      } else if (o.name == "gl_FragDepth") {
        iface_.writes_depth = true;
        code_.insts.push_back(ir::Inst{Op::StoreDepth, kNone, o.reg});
      }
    }
    return;
  }
  std::vector<std::pair<int, Operand>> stores;  // output float, register
  for (const OutputVar& o : outputs_) {
    auto store_range = [&](int first_float, int reg, int n) {
      for (int c = 0; c < n; ++c) stores.emplace_back(kOutFirstVarying + first_float + c, reg + c);
    };
    if (o.name == "gl_Position") {
      for (int c = 0; c < 4; ++c) stores.emplace_back(kOutPosition + c, o.reg + c);
      continue;
    }
    if (o.name == "gl_PointSize") {
      iface_.writes_point_size = true;
      stores.emplace_back(kOutPointSize, o.reg);
      continue;
    }
    if (o.name == "gl_ClipVertex") continue;  // user clip planes use eye coordinates (README.md)
    std::string target = o.name;
    bool back = false;
    if (o.name == "gl_FrontColor") target = "gl_Color";
    else if (o.name == "gl_BackColor") target = "gl_Color", back = true;
    else if (o.name == "gl_FrontSecondaryColor") target = "gl_SecondaryColor";
    else if (o.name == "gl_BackSecondaryColor") target = "gl_SecondaryColor", back = true;
    VaryingVar* v = iface_.find_varying(target);
    if (!v && !iface_.has_fragment_shader && starts_with_gl(target)) {
      VarType t = o.type;
      if (target == "gl_Color" || target == "gl_SecondaryColor") t = VarType::vec(4);
      v = &iface_.add_varying(target, t);
    }
    if (!v) continue;  // not read by the fragment shader
    if (back) {
      if (v->back_offset < 0) {
        v->back_offset = iface_.varying_floats;
        iface_.varying_floats += 4;
      }
      store_range(v->back_offset, o.reg, 4);
      continue;
    }
    if (!starts_with_gl(target) && !(v->type == o.type))
      fail("error: vertex shader output `" + o.name + "' declared as type `" + type_name(o.type) +
           "', but fragment shader input declared as type `" + type_name(v->type) + "'\n");
    const int n = std::min(o.type.size(), v->type.size());
    store_range(v->offset, o.reg, n);
  }
  std::vector<bool> written(kOutFirstVarying + iface_.varying_floats, false);
  for (auto& [index, reg] : stores) {
    written[index] = true;
    code_.insts.push_back(ir::Inst{Op::StoreOutput, kNone, reg, kNone, kNone, index});
  }
  for (size_t i = 0; i < written.size(); ++i)
    if (!written[i]) code_.insts.push_back(ir::Inst{Op::StoreOutput, kNone, k(0.0f), kNone, kNone, static_cast<int>(i)});
  // Fragment inputs that the vertex shader does not declare.
  if (iface_.has_fragment_shader)
    for (const VaryingVar& v : iface_.varyings) {
      if (starts_with_gl(v.name)) continue;
      auto d = declared_outputs_.find(v.name);
      if (d == declared_outputs_.end())
        fail("error: fragment shader varying " + v.name + " not written by vertex shader\n");
      if (!(d->second == v.type))
        fail("error: vertex shader output `" + v.name + "' declared as type `" + type_name(d->second) +
             "', but fragment shader input declared as type `" + type_name(v.type) + "'\n");
    }
}

}  // namespace

bool lower_stage(Stage stage, const glslang::TIntermediate& tree, Interface& iface, ir::Code& code,
                 std::string& error) {
  try {
    Lowerer(stage, iface, code).run(tree);
    return true;
  } catch (const LowerError& e) {
    error = e.message;
    return false;
  }
}

}  // namespace pineda::shader
