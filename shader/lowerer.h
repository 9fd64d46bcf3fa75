// The lowering of one stage (shader/lower.h) from the inside: the Lowerer, which walks
// glslang's typed tree and emits IR, and what its parts share. Every value becomes one
// operand per scalar component, user functions are inlined at each call, control flow becomes
// the structured marker operations that the executor runs with lane masks.
#pragma once
#include <glslang/Include/intermediate.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include <algorithm>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "shader/interface.h"
#include "shader/ir.h"

namespace pineda::shader::lowering {

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
[[noreturn]] inline void fail(const std::string& message) { throw LowerError{message}; }

inline constexpr int kMaxTextureCoords = 8;
inline constexpr int kMaxInlineDepth = 64;
// Bounds on what one stage may lower to, so that huge arrays or an explosion of inlined
// calls end in a link error rather than exhausting memory.
inline constexpr int kMaxInstructions = 1 << 18;
inline constexpr int kMaxRegisters = 1 << 18;
// Expressions nested in expressions, through inlined calls too: rv() recurses once per level
// (several kB of stack each under AddressSanitizer).
inline constexpr int kMaxExpressionDepth = 512;

inline bool starts_with_gl(const std::string& name) { return name.compare(0, 3, "gl_") == 0; }

// glslang's type as a flattened VarType (lower_types.cpp).
VarType var_type(const TType& t, const std::string& name = {});

// Questions about glslang's tree (lower_tree.cpp).
bool is_assign(TOperator op);
TOperator base_of_assign(TOperator op);  // EOpAddAssign -> EOpAdd, ...; EOpNull otherwise
bool has_side_effects(TIntermNode* node);
// Return statements of a function body, and whether the last statement is one.
void count_returns(TIntermNode* node, int& count);
void collect_locals(TIntermNode* node, std::vector<TIntermSymbol*>& out);

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


Place whole(Place::Kind kind, int base, const VarType& type);
BuiltinAttribute builtin_attribute(const std::string& name);

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
  Val builtin_unary(TIntermUnary* u, const Val& a, const VarType& at);
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
  bool es_ = false;  // GLSL ES 1.00
};

}  // namespace pineda::shader::lowering
