#include "shader/execute.h"

#include <cmath>
#include <algorithm>
#include <cstring>
#include <memory>

namespace pineda::shader {

using ir::Op;
using ir::Operand;

namespace {

constexpr LaneMask kAllLanes = 0xFFFF;
constexpr int kStackRegisters = 256;
constexpr int kStackFrames = 64;
// Loop iterations one invocation may run in total (all loops together): a shader with an
// unbounded loop ends instead of hanging the draw.
constexpr int kIterationBudget = 1 << 18;

struct Frame {
  Op kind;
  LaneMask entry;    // lanes that continue after the construct
  LaneMask cond;     // if: lanes that took the then branch
  LaneMask running;  // loop: lanes still iterating
};

inline int clamp_index(float x, int limit) {
  if (!(x >= 0.0f)) return 0;  // negative or NaN
  if (x >= static_cast<float>(limit)) return limit;
  return static_cast<int>(x);
}

inline void blend(float* d, const float* t, LaneMask mask) {
  for (int l = 0; l < kLanes; ++l)
    if (mask >> l & 1) d[l] = t[l];
}

}  // namespace

void StageCode::prepare() {
  exec = code.insts;
  for (ir::Inst& in : exec) {
    if (in.op == Op::Texture) continue;  // its operands stay in code.textures
    in.d = offset(in.d);
    in.a = offset(in.a);
    in.b = offset(in.b);
    in.c = offset(in.c);
    if (in.op == Op::Gather || in.op == Op::Scatter) in.i0 = offset(in.i0);
  }
  int depth = 0;
  max_depth = 0;
  for (const ir::Inst& in : code.insts) {
    if (in.op == Op::IfBegin || in.op == Op::LoopBegin || in.op == Op::FuncBegin) max_depth = std::max(max_depth, ++depth);
    if (in.op == Op::EndIf || in.op == Op::LoopEnd || in.op == Op::FuncEnd) --depth;
  }
  constant_lanes.resize(code.constants.size() * kLanes);
  for (size_t i = 0; i < code.constants.size(); ++i)
    for (int l = 0; l < kLanes; ++l) constant_lanes[i * kLanes + l] = code.constants[i];
}

LaneMask execute(const StageCode& stage, Stage kind, LaneMask mask, const LaneIo& io) {
  const ir::FlushDenormals flush;
  const ir::Code& code = stage.code;
  // One buffer: the constants' lanes, then the registers.
  const size_t floats = (code.constants.size() + static_cast<size_t>(code.registers)) * kLanes;
  alignas(64) float stack_buffer[kStackRegisters * kLanes];
  std::unique_ptr<float[]> heap_buffer;
  float* buf = stack_buffer;
  if (floats > static_cast<size_t>(kStackRegisters) * kLanes) {
    heap_buffer.reset(new float[floats]);
    buf = heap_buffer.get();
  }
  std::memcpy(buf, stage.constant_lanes.data(), sizeof(float) * stage.constant_lanes.size());
  // Lanes a masked write skips keep what they held: start from zeros, so that every run of
  // the same inputs gives the same values even where GLSL leaves them undefined.
  std::memset(buf + stage.constant_lanes.size(), 0, sizeof(float) * kLanes * static_cast<size_t>(code.registers));
  Frame stack_frames[kStackFrames];
  std::unique_ptr<Frame[]> heap_frames;
  Frame* frames = stack_frames;
  if (stage.max_depth > kStackFrames) {
    heap_frames.reset(new Frame[stage.max_depth]);
    frames = heap_frames.get();
  }
  int top = 0;  // number of frames
  LaneMask discarded = 0;
  int budget = kIterationBudget;
  auto src = [buf](int32_t offset) -> const float* { return buf + offset; };
  auto reg = [buf](int32_t offset) -> float* { return buf + offset; };
  // Texture lookups keep IR operands.
  auto ir_src = [&](Operand o) -> float* { return buf + stage.offset(o); };
  // Removes `lanes` from every frame above the innermost one of `stop` kind (all frames when
  // stop is Discard).
  auto remove_lanes = [&](LaneMask lanes, Op stop) {
    for (int f = top - 1; f >= 0; --f) {
      Frame& fr = frames[f];
      if (fr.kind == stop) {
        if (stop == Op::LoopBegin) fr.running &= ~lanes;
        return;
      }
      fr.entry &= ~lanes;
      fr.running &= ~lanes;
    }
  };

// Each lane's value goes to a local array first (no aliasing with the operands, so the
// loop vectorizes), then to the register: whole, or blended under the mask.
#define LANEWISE(EXPR)                                                  \
  do {                                                                  \
    float T[kLanes];                                                    \
    for (int l = 0; l < kLanes; ++l) T[l] = (EXPR);                     \
    float* D = reg(in.d);                                               \
    if (mask == kAllLanes) std::memcpy(D, T, sizeof T);                 \
    else blend(D, T, mask);                                             \
  } while (0)
#define UNARY(F) { const float* A = src(in.a); LANEWISE(F); break; }
#define BINARY(F) { const float* A = src(in.a); const float* B = src(in.b); LANEWISE(F); break; }
#define TERNARY(F) { const float* A = src(in.a); const float* B = src(in.b); const float* C = src(in.c); LANEWISE(F); break; }

  const ir::Inst* insts = stage.exec.data();
  const size_t n = stage.exec.size();
  for (size_t pc = 0; pc < n; ++pc) {
    const ir::Inst& in = insts[pc];
    if (mask == 0) {
      if (top == 0) break;  // every lane returned or discarded
      if (in.op > Op::Discard) continue;  // nothing to compute; structure still runs
    }
    switch (in.op) {
      case Op::IfBegin: {
        const float* A = src(in.a);
        LaneMask taken = 0;
        for (int l = 0; l < kLanes; ++l) taken |= static_cast<LaneMask>((A[l] != 0.0f) << l);
        frames[top++] = Frame{Op::IfBegin, mask, static_cast<LaneMask>(taken & mask), 0};
        mask &= taken;
        if (mask == 0) pc = static_cast<size_t>(in.i0) - 1;
        break;
      }
      case Op::Else: {
        Frame& f = frames[top - 1];
        mask = f.entry & ~f.cond;
        if (mask == 0) pc = static_cast<size_t>(in.i0) - 1;
        break;
      }
      case Op::EndIf:
        mask = frames[--top].entry;
        break;
      case Op::LoopBegin:
        if (mask == 0) {
          pc = static_cast<size_t>(in.i0);
          break;
        }
        frames[top++] = Frame{Op::LoopBegin, mask, 0, mask};
        break;
      case Op::ContinuePoint:
        mask = frames[top - 1].running;
        break;
      case Op::LoopEnd: {
        Frame& f = frames[top - 1];
        if (f.running != 0 && --budget > 0) {
          mask = f.running;
          pc = static_cast<size_t>(in.i0) - 1;
        } else {
          mask = f.entry;
          --top;
        }
        break;
      }
      case Op::Break:
        remove_lanes(mask, Op::LoopBegin);
        mask = 0;
        break;
      case Op::BreakIfNot: {
        const float* A = src(in.a);
        LaneMask leave = 0;
        for (int l = 0; l < kLanes; ++l) leave |= static_cast<LaneMask>((A[l] == 0.0f) << l);
        leave &= mask;
        remove_lanes(leave, Op::LoopBegin);
        mask &= ~leave;
        break;
      }
      case Op::Continue: {
        // Lanes skip to the loop's continue point: out of every frame inside the loop.
        for (int f = top - 1; f >= 0 && frames[f].kind != Op::LoopBegin; --f) frames[f].entry &= ~mask;
        mask = 0;
        break;
      }
      case Op::FuncBegin:
        frames[top++] = Frame{Op::FuncBegin, mask, 0, 0};
        break;
      case Op::FuncEnd:
        mask = frames[--top].entry;
        break;
      case Op::Return:
        remove_lanes(mask, Op::FuncBegin);
        mask = 0;
        break;
      case Op::Discard:
        discarded |= mask;
        remove_lanes(mask, Op::Discard);
        mask = 0;
        break;
          case Op::Mov: UNARY(A[l])
          case Op::LoadUniform: {
            const float v = io.uniforms[in.i0];
            LANEWISE(v);
            break;
          }
          case Op::GatherUniform: {
            const float* A = src(in.a);
            LANEWISE(io.uniforms[in.i0 + clamp_index(A[l], in.i1)]);
            break;
          }
          case Op::Gather: {
            const float* A = src(in.a);
            LANEWISE(buf[in.i0 + clamp_index(A[l], in.i1) * kLanes + l]);
            break;
          }
          case Op::Scatter: {
            const float* A = src(in.a);
            const float* B = src(in.b);
            for (int l = 0; l < kLanes; ++l)
              if (mask >> l & 1) buf[in.i0 + clamp_index(A[l], in.i1) * kLanes + l] = B[l];
            break;
          }
          case Op::LoadInput: {
            const float* I = io.inputs + static_cast<size_t>(in.i0) * kLanes;
            LANEWISE(I[l]);
            break;
          }
          case Op::LoadVarying: {
            const float* V = io.block->varyings + static_cast<size_t>(in.i0) * kLanes;
            LANEWISE(V[l]);
            break;
          }
          case Op::LoadFragCoord: {
            const float* V = io.block->frag_coord[in.i0];
            LANEWISE(V[l]);
            break;
          }
          case Op::LoadPointCoord: {
            const float* V = io.block->point_coord[in.i0];
            LANEWISE(V[l]);
            break;
          }
          case Op::LoadFrontFacing: {
            const LaneMask ff = io.block->front_facing;
            LANEWISE((ff >> l & 1) ? 1.0f : 0.0f);
            break;
          }
          case Op::StoreOutput: {
            const float* A = src(in.a);
            std::memcpy(io.outputs + static_cast<size_t>(in.i0) * kLanes, A, sizeof(float) * kLanes);
            break;
          }
          case Op::StoreColor: {
            const float* A = src(in.a);
            if (in.i1) {
              for (int b = 0; b < kMaxDrawBuffers; ++b) std::memcpy(io.block->color[b][in.i0 & 3], A, sizeof(float) * kLanes);
            } else {
              std::memcpy(io.block->color[in.i0 >> 2][in.i0 & 3], A, sizeof(float) * kLanes);
            }
            break;
          }
          case Op::StoreDepth:
            std::memcpy(io.block->depth, src(in.a), sizeof(float) * kLanes);
            break;
          case Op::Texture: {
            const ir::TextureLookup& t = code.textures[in.i0];
            float coords[4][kLanes];
            for (int c = 0; c < 4; ++c) std::memcpy(coords[c], ir_src(t.coord[c]), sizeof(float) * kLanes);
            float out[4][kLanes] = {};
            if (io.textures) {
              const float* S = ir_src(t.sampler);
              int first = 0;
              while (!(mask >> first & 1)) ++first;
              const float unit_f = S[first];
              const int unit = unit_f >= 0.0f && unit_f < 256.0f ? static_cast<int>(unit_f) : 0;
              io.textures->sample(unit, t.kind, coords, t.mode, t.lod == ir::kNone ? nullptr : ir_src(t.lod), mask, out);
            }
            for (int c = 0; c < 4; ++c) {
              float* D = ir_src(t.dst[c]);
              if (mask == kAllLanes) std::memcpy(D, out[c], sizeof(float) * kLanes);
              else blend(D, out[c], mask);
            }
            break;
          }
          case Op::Neg: UNARY(-A[l])
          case Op::Abs: UNARY(std::fabs(A[l]))
          case Op::Sign: UNARY(A[l] > 0.0f ? 1.0f : (A[l] < 0.0f ? -1.0f : 0.0f))
          case Op::Floor: UNARY(ir::lane_floor(A[l]))
          case Op::Ceil: UNARY(ir::lane_ceil(A[l]))
          case Op::Fract: UNARY(A[l] - ir::lane_floor(A[l]))
          case Op::Trunc: UNARY(ir::lane_trunc(A[l]))
          case Op::Sqrt: UNARY(std::sqrt(A[l]))
          case Op::Rsq: UNARY(1.0f / std::sqrt(A[l]))
          case Op::NormScale: UNARY(A[l] > 0.0f ? 1.0f / std::sqrt(A[l]) : 0.0f)
          case Op::Exp: UNARY(std::exp(A[l]))
          case Op::Log: UNARY(std::log(A[l]))
          case Op::Exp2: UNARY(std::exp2(A[l]))
          case Op::Log2: UNARY(std::log2(A[l]))
          case Op::Sin: UNARY(std::sin(A[l]))
          case Op::Cos: UNARY(std::cos(A[l]))
          case Op::Tan: UNARY(std::tan(A[l]))
          case Op::Asin: UNARY(std::asin(A[l]))
          case Op::Acos: UNARY(std::acos(A[l]))
          case Op::Atan: UNARY(std::atan(A[l]))
          case Op::Not: UNARY(A[l] == 0.0f ? 1.0f : 0.0f)
          case Op::ToBool: UNARY(A[l] != 0.0f ? 1.0f : 0.0f)
          case Op::Ddx: UNARY(kind == Stage::Fragment ? A[l | 1] - A[l & ~1] : 0.0f)
          case Op::Ddy: UNARY(kind == Stage::Fragment ? A[l | 2] - A[l & ~2] : 0.0f)
          case Op::Add: BINARY(A[l] + B[l])
          case Op::Sub: BINARY(A[l] - B[l])
          case Op::Mul: BINARY(A[l] * B[l])
          case Op::Div: BINARY(A[l] / B[l])
          case Op::Mod: BINARY(A[l] - B[l] * ir::lane_floor(A[l] / B[l]))
          case Op::Min: BINARY(ir::lane_min(A[l], B[l]))
          case Op::Max: BINARY(ir::lane_max(A[l], B[l]))
          case Op::Pow: BINARY(std::pow(A[l], B[l]))
          case Op::Atan2: BINARY(std::atan2(A[l], B[l]))
          case Op::Step: BINARY(B[l] < A[l] ? 0.0f : 1.0f)
          case Op::Lt: BINARY(A[l] < B[l] ? 1.0f : 0.0f)
          case Op::Le: BINARY(A[l] <= B[l] ? 1.0f : 0.0f)
          case Op::Gt: BINARY(A[l] > B[l] ? 1.0f : 0.0f)
          case Op::Ge: BINARY(A[l] >= B[l] ? 1.0f : 0.0f)
          case Op::Eq: BINARY(A[l] == B[l] ? 1.0f : 0.0f)
          case Op::Ne: BINARY(A[l] != B[l] ? 1.0f : 0.0f)
          case Op::And: BINARY((A[l] != 0.0f && B[l] != 0.0f) ? 1.0f : 0.0f)
          case Op::Or: BINARY((A[l] != 0.0f || B[l] != 0.0f) ? 1.0f : 0.0f)
          case Op::Xor: BINARY(((A[l] != 0.0f) != (B[l] != 0.0f)) ? 1.0f : 0.0f)
          case Op::Clamp: TERNARY(ir::lane_min(ir::lane_max(A[l], B[l]), C[l]))
          case Op::Mix: TERNARY(A[l] * (1.0f - C[l]) + B[l] * C[l])
          case Op::Smoothstep: TERNARY(ir::lane_smoothstep(A[l], B[l], C[l]))
          case Op::Select: TERNARY(A[l] != 0.0f ? B[l] : C[l])
          case Op::Mad: TERNARY(A[l] * B[l] + C[l])
          default: break;
    }
  }
#undef LANEWISE
#undef UNARY
#undef BINARY
#undef TERNARY
  return discarded;
}

}  // namespace pineda::shader
