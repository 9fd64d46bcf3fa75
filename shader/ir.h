// Pineda's shader IR: a flat list of scalar operations on 16-lane float registers, with
// structured control flow as marker operations that the executor runs with lane masks.
// See shader/README.md for the design.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "shader/program.h"

namespace pineda::shader::ir {

// An operand is a register (>= 0) or a constant (< 0: constant index ~operand).
using Operand = int32_t;
constexpr Operand kNone = INT32_MIN;
inline bool is_const(Operand o) { return o < 0 && o != kNone; }
inline int const_index(Operand o) { return ~o; }
inline Operand const_operand(int index) { return ~index; }

enum class Op : uint8_t {
  // Structure (no destination). Jump targets are instruction indices in i0/i1.
  IfBegin,        // a: condition; i0: the Else (or EndIf) to jump to when no lane takes the branch
  Else,           // i0: the EndIf to jump to when no lane takes the else branch
  EndIf,
  LoopBegin,      // i0: the LoopEnd
  ContinuePoint,  // lanes that executed Continue rejoin here (before the loop's increment)
  LoopEnd,        // i0: the first instruction of the body (after LoopBegin)
  Break,
  BreakIfNot,     // a: lanes where a == 0 leave the loop
  Continue,
  FuncBegin,      // an inlined function body that returns early somewhere
  FuncEnd,
  Return,
  Discard,
  // Moves and loads (d: destination register).
  Mov,            // d = a (i1 = 1: a "soft" zero initialisation of a declared variable)
  LoadUniform,    // d = uniforms[i0]
  GatherUniform,  // d = uniforms[i0 + clamp(int(a), 0, i1)]
  Gather,         // d = reg[i0 + clamp(int(a), 0, i1)]
  Scatter,        // reg[i0 + clamp(int(a), 0, i1)] = b (under the mask)
  LoadInput,      // d = vertex input float i0 (slot * 4 + component)
  LoadVarying,    // d = varying float i0
  LoadFragCoord,  // d = gl_FragCoord component i0
  LoadFrontFacing,
  LoadPointCoord, // d = gl_PointCoord component i0
  StoreOutput,    // vertex output float i0 = a (all lanes)
  StoreColor,     // fragment colour: buffer i0 >> 2, component i0 & 3 = a; i1 = 1: gl_FragColor (buffer 0, read for every buffer)
  StoreDepth,     // gl_FragDepth = a
  Texture,        // i0: index into Code::textures
  // Unary (d = f(a)).
  Neg, Abs, Sign, Floor, Ceil, Fract, Trunc, Sqrt, Rsq, NormScale, Exp, Log, Exp2, Log2,
  Sin, Cos, Tan, Asin, Acos, Atan, Not, ToBool, Ddx, Ddy,
  // Binary (d = f(a, b)).
  Add, Sub, Mul, Div, Mod, Min, Max, Pow, Atan2, Step, Lt, Le, Gt, Ge, Eq, Ne, And, Or, Xor,
  // Ternary (d = f(a, b, c)).
  Clamp, Mix, Smoothstep, Select, Mad,
  Count
};

const char* op_name(Op op);
// The number of value operands among a, b, c for arithmetic and moves (inline: it runs once
// per instruction of a draw's uniform-only operations).
inline int op_arity(Op op) {
  if (op == Op::Mov) return 1;
  if (op >= Op::Neg && op <= Op::Ddy) return 1;
  if (op >= Op::Add && op <= Op::Xor) return 2;
  if (op >= Op::Clamp && op <= Op::Mad) return 3;
  return 0;
}
bool op_is_pure_arith(Op op);  // Neg..Mad, and Mov: d depends only on a, b, c

struct Inst {
  Op op;
  Operand d = kNone, a = kNone, b = kNone, c = kNone;
  int32_t i0 = 0, i1 = 0;
};

struct TextureLookup {
  SamplerKind kind = SamplerKind::Tex2D;
  LodMode mode = LodMode::Implicit;
  Operand sampler = kNone;      // holds the texture unit
  Operand coord[4] = {kNone, kNone, kNone, kNone};
  Operand lod = kNone;          // bias or level (kNone for Implicit)
  Operand dst[4] = {kNone, kNone, kNone, kNone};
};

struct Code {
  std::vector<Inst> insts;
  std::vector<float> constants;
  std::vector<TextureLookup> textures;
  int registers = 0;

  Operand constant(float value);  // reuses an equal constant (bitwise)
  Operand new_register() { return registers++; }
  Operand new_registers(int n) { int r = registers; registers += n; return r; }
  float const_value(Operand o) const { return constants[const_index(o)]; }
};

// Per-lane helpers written so that the executor's 16-lane loops vectorize, used by constant
// folding too so that folded and executed values are identical. min/max return the number
// when one operand is NaN; floor/ceil/trunc are exact for every float.
inline float lane_max(float a, float b) { return (a > b || b != b) ? a : b; }
inline float lane_min(float a, float b) { return (a < b || b != b) ? a : b; }
inline float lane_trunc(float x) {
  // Floats of magnitude 2^23 and more (and NaN, inf) are already integral.
  return (x > -8388608.0f && x < 8388608.0f) ? static_cast<float>(static_cast<int32_t>(x)) : x;
}
inline float lane_floor(float x) {
  float t = lane_trunc(x);
  return t > x ? t - 1.0f : t;
}
inline float lane_ceil(float x) {
  float t = lane_trunc(x);
  return t < x ? t + 1.0f : t;
}

inline float lane_smoothstep(float e0, float e1, float x) {
  float t = lane_min(lane_max((x - e0) / (e1 - e0), 0.0f), 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Denormals are flushed to zero (inputs and results) while shaders run and while their
// constants fold, as GPUs and GLSL allow: same values either way, and no slow denormal path.
// The rest of the modes are the defaults (round to nearest, exceptions masked), whatever the
// application set: its rounding mode would otherwise change results and split the tiers (the
// compiled tier makes floor's zeros +0 by adding +0), an exception it unmasked would trap.
class FlushDenormals {
 public:
  // already_set: the caller runs with them set (raster::Scene::run_tile does for shader draws),
  // and MXCSR is neither read nor written (its read alone stalled: 2-3% of a shader scene).
  explicit FlushDenormals(bool already_set = false);
  ~FlushDenormals();
  FlushDenormals(const FlushDenormals&) = delete;
  FlushDenormals& operator=(const FlushDenormals&) = delete;

 private:
  unsigned saved_;
};

// Scalar semantics shared by the executor and constant folding.
float eval_unary(Op op, float a);
float eval_binary(Op op, float a, float b);
float eval_ternary(Op op, float a, float b, float c);

std::string dump(const Code& code);

}  // namespace pineda::shader::ir
