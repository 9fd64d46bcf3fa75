#include "shader/ir.h"

#include <cmath>
#include <cstring>
#include <sstream>

#include "raster/float_modes.h"  // the shader modes, and PINEDA_HAS_MXCSR where there is MXCSR

// lane_pow.inc and lane_sin_cos.inc work on 32-byte double vectors in helpers that are always inlined.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace pineda::shader::ir {

namespace {
#include "shader/lane_pow.inc"
#include "shader/lane_sin_cos.inc"

// The executor's pow over vectors, for one value.
float pow_value(float x, float y) {
  const LaneTypes<4>::F r = lane_pow<4>(LaneTypes<4>::F{x, x, x, x}, LaneTypes<4>::F{y, y, y, y});  // not 0 + x: -0 stays -0
  return r[0];
}

// The executor's exp and exp2 over vectors, for one value.
float exp_value(float x, bool natural) { return lane_exp<4>(LaneTypes<4>::F{x, x, x, x}, natural)[0]; }

// The executor's sin and cos over vectors, for one value.
float sin_cos_value(float x, bool cosine) {
  return lane_sin_cos<4>(LaneTypes<4>::F{x, x, x, x}, cosine)[0];
}

const char* const kOpNames[] = {
    "if", "else", "endif", "loop", "continue_point", "endloop", "break", "break_if_not",
    "continue", "func", "endfunc", "return", "discard",
    "mov", "uniform", "gather_uniform", "gather", "scatter", "input", "varying", "frag_coord",
    "front_facing", "point_coord", "out", "color", "depth", "texture",
    "neg", "abs", "sign", "floor", "ceil", "fract", "trunc", "sqrt", "rsq", "norm_scale", "exp",
    "log", "exp2", "log2", "sin", "cos", "tan", "asin", "acos", "atan", "not", "to_bool", "ddx",
    "ddy",
    "add", "sub", "mul", "div", "mod", "min", "max", "pow", "atan2", "step", "lt", "le", "gt",
    "ge", "eq", "ne", "and", "or", "xor",
    "clamp", "mix", "smoothstep", "select", "mad"};
static_assert(sizeof(kOpNames) / sizeof(kOpNames[0]) == static_cast<size_t>(Op::Count));
}  // namespace

#ifdef PINEDA_HAS_MXCSR
namespace {
constexpr unsigned kShaderModes = raster::kShaderFloatModes;
constexpr unsigned kStatusFlags = 0x3F;  // MXCSR's exception flags: they do not count
}  // namespace

// A tile sets the modes once for a run of programmable draws (raster::Scene::run_tile), the
// vertex stage once per piece: then the shader's runs are told so, or find them set, and the
// MXCSR writes are left out.
FlushDenormals::FlushDenormals(bool already_set) : saved_(already_set ? kShaderModes : _mm_getcsr()) {
  if ((saved_ & ~kStatusFlags) != kShaderModes) _mm_setcsr(kShaderModes);
}
FlushDenormals::~FlushDenormals() {
  if ((saved_ & ~kStatusFlags) != kShaderModes) _mm_setcsr(saved_);
}
#else
FlushDenormals::FlushDenormals(bool) : saved_(0) {}
FlushDenormals::~FlushDenormals() {}
#endif

const char* op_name(Op op) { return kOpNames[static_cast<int>(op)]; }

bool op_is_pure_arith(Op op) {
  return op == Op::Mov || (op >= Op::Neg && op <= Op::Mad && op != Op::Ddx && op != Op::Ddy);
}

Operand Code::constant(float value) {
  for (size_t i = 0; i < constants.size(); ++i)
    if (std::memcmp(&constants[i], &value, sizeof value) == 0) return const_operand(static_cast<int>(i));
  constants.push_back(value);
  return const_operand(static_cast<int>(constants.size() - 1));
}

float eval_unary(Op op, float a) {
  switch (op) {
    case Op::Mov: return a;
    case Op::Neg: return -a;
    case Op::Abs: return std::fabs(a);
    case Op::Sign: return a > 0.0f ? 1.0f : (a < 0.0f ? -1.0f : 0.0f);
    case Op::Floor: return lane_floor(a);
    case Op::Ceil: return lane_ceil(a);
    case Op::Fract: return a - lane_floor(a);
    case Op::Trunc: return lane_trunc(a);
    case Op::Sqrt: return std::sqrt(a);
    case Op::Rsq: return 1.0f / std::sqrt(a);
    // The scale that normalizes a vector of squared length a; 0 for a zero vector.
    case Op::NormScale: return a > 0.0f ? 1.0f / std::sqrt(a) : 0.0f;
    case Op::Exp: return exp_value(a, true);
    case Op::Log: return std::log(a);
    case Op::Exp2: return exp_value(a, false);
    case Op::Log2: return std::log2(a);
    case Op::Sin: return sin_cos_value(a, false);
    case Op::Cos: return sin_cos_value(a, true);
    case Op::Tan: return std::tan(a);
    case Op::Asin: return std::asin(a);
    case Op::Acos: return std::acos(a);
    case Op::Atan: return std::atan(a);
    case Op::Not: return a == 0.0f ? 1.0f : 0.0f;
    case Op::ToBool: return a != 0.0f ? 1.0f : 0.0f;
    default: return 0.0f;
  }
}

float eval_binary(Op op, float a, float b) {
  switch (op) {
    case Op::Add: return a + b;
    case Op::Sub: return a - b;
    case Op::Mul: return a * b;
    case Op::Div: return a / b;
    case Op::Mod: return a - b * lane_floor(a / b);
    // GLSL min/max of a NaN is undefined; fmin/fmax pick the number.
    case Op::Min: return lane_min(a, b);
    case Op::Max: return lane_max(a, b);
    case Op::Pow: return pow_value(a, b);
    case Op::Atan2: return std::atan2(a, b);
    case Op::Step: return b < a ? 0.0f : 1.0f;
    case Op::Lt: return a < b ? 1.0f : 0.0f;
    case Op::Le: return a <= b ? 1.0f : 0.0f;
    case Op::Gt: return a > b ? 1.0f : 0.0f;
    case Op::Ge: return a >= b ? 1.0f : 0.0f;
    case Op::Eq: return a == b ? 1.0f : 0.0f;
    case Op::Ne: return a != b ? 1.0f : 0.0f;
    case Op::And: return (a != 0.0f && b != 0.0f) ? 1.0f : 0.0f;
    case Op::Or: return (a != 0.0f || b != 0.0f) ? 1.0f : 0.0f;
    case Op::Xor: return ((a != 0.0f) != (b != 0.0f)) ? 1.0f : 0.0f;
    default: return 0.0f;
  }
}

float eval_ternary(Op op, float a, float b, float c) {
  switch (op) {
    case Op::Clamp: return lane_min(lane_max(a, b), c);
    case Op::Mix: return a * (1.0f - c) + b * c;
    case Op::Smoothstep: return lane_smoothstep(a, b, c);
    case Op::Select: return a != 0.0f ? b : c;
    case Op::Mad: return a * b + c;
    default: return 0.0f;
  }
}

namespace {
void print_operand(std::ostringstream& out, const Code& code, Operand o) {
  if (o == kNone) out << "_";
  else if (is_const(o)) out << code.const_value(o);
  else out << "r" << o;
}
}  // namespace

std::string dump(const Code& code) {
  std::ostringstream out;
  int depth = 0;
  for (size_t pc = 0; pc < code.insts.size(); ++pc) {
    const Inst& in = code.insts[pc];
    if (in.op == Op::Else || in.op == Op::EndIf || in.op == Op::LoopEnd || in.op == Op::FuncEnd ||
        in.op == Op::ContinuePoint)
      --depth;
    out << pc << ":" << std::string(2 + 2 * (depth > 0 ? depth : 0), ' ');
    if (in.d != kNone) {
      print_operand(out, code, in.d);
      out << " = ";
    }
    out << op_name(in.op);
    for (Operand o : {in.a, in.b, in.c})
      if (o != kNone) {
        out << " ";
        print_operand(out, code, o);
      }
    switch (in.op) {
      case Op::IfBegin: case Op::Else: case Op::LoopBegin: case Op::LoopEnd:
      case Op::LoadUniform: case Op::LoadInput: case Op::LoadVarying: case Op::LoadFragCoord:
      case Op::LoadPointCoord: case Op::StoreOutput:
        out << " #" << in.i0;
        break;
      case Op::StoreColor: out << " #" << in.i0 << (in.i1 ? " all" : ""); break;
      case Op::GatherUniform: case Op::Gather: case Op::Scatter:
        out << " [" << in.i0 << "+0.." << in.i1 << "]";
        break;
      case Op::Texture: {
        const TextureLookup& t = code.textures[in.i0];
        out << " kind" << static_cast<int>(t.kind) << " lod" << static_cast<int>(t.mode) << " unit ";
        print_operand(out, code, t.sampler);
        out << " (";
        for (Operand c : t.coord) { out << " "; print_operand(out, code, c); }
        out << " ) lod ";
        print_operand(out, code, t.lod);
        out << " ->";
        for (Operand d : t.dst) { out << " "; print_operand(out, code, d); }
        break;
      }
      default: break;
    }
    out << "\n";
    if (in.op == Op::IfBegin || in.op == Op::Else || in.op == Op::LoopBegin || in.op == Op::FuncBegin ||
        in.op == Op::ContinuePoint)
      ++depth;
  }
  out << "; " << code.registers << " registers, " << code.constants.size() << " constants\n";
  return out.str();
}

}  // namespace pineda::shader::ir
