// The per-fragment operations on single values: comparisons, stencil ops, blending, logic ops.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "raster/draw_state.h"

namespace pineda::raster {

template <typename T>
inline bool compare(CompareFunc f, T incoming, T stored) {
  switch (f) {
    case CompareFunc::Never: return false;
    case CompareFunc::Less: return incoming < stored;
    case CompareFunc::Equal: return incoming == stored;
    case CompareFunc::LessEqual: return incoming <= stored;
    case CompareFunc::Greater: return incoming > stored;
    case CompareFunc::NotEqual: return incoming != stored;
    case CompareFunc::GreaterEqual: return incoming >= stored;
    case CompareFunc::Always: return true;
  }
  return true;
}

// compare over the lanes of vectors (GCC vector extensions) of unsigned integers: all ones in
// the lanes that pass.
template <typename V>
inline V compare_lanes(CompareFunc f, V incoming, V stored) {
  switch (f) {
    case CompareFunc::Never: return V{};
    case CompareFunc::Less: return reinterpret_cast<V>(incoming < stored);
    case CompareFunc::Equal: return reinterpret_cast<V>(incoming == stored);
    case CompareFunc::LessEqual: return reinterpret_cast<V>(incoming <= stored);
    case CompareFunc::Greater: return reinterpret_cast<V>(incoming > stored);
    case CompareFunc::NotEqual: return reinterpret_cast<V>(incoming != stored);
    case CompareFunc::GreaterEqual: return reinterpret_cast<V>(incoming >= stored);
    case CompareFunc::Always: break;
  }
  return ~V{};
}

// The alpha test of a draw whose state.alpha_test is on: its function and reference, and on a
// sample's record under alpha to coverage (DrawRecord::alpha_to_coverage) that sample's
// threshold. `Record` is DrawRecord (declared after this header).
template <typename Record>
inline bool alpha_passes(const Record& d, float alpha) {
  return compare(d.state.alpha_func, alpha, d.alpha_ref) && (!d.alpha_to_coverage || alpha >= d.coverage_alpha_min);
}

inline uint8_t stencil_op(StencilOp op, uint8_t value, uint8_t ref) {
  switch (op) {
    case StencilOp::Keep: return value;
    case StencilOp::Zero: return 0;
    case StencilOp::Replace: return ref;
    case StencilOp::Incr: return value == 255 ? 255 : value + 1;
    case StencilOp::Decr: return value == 0 ? 0 : value - 1;
    case StencilOp::Invert: return static_cast<uint8_t>(~value);
    case StencilOp::IncrWrap: return static_cast<uint8_t>(value + 1);
    case StencilOp::DecrWrap: return static_cast<uint8_t>(value - 1);
  }
  return value;
}

// NaN-safe clamp to [0, 1] (NaN becomes 0).
inline float clamp01(float v) { return v > 0.f ? (v < 1.f ? v : 1.f) : 0.f; }

// Nearest, ties to even (as llvmpipe converts): 2^23 + s, for s in [0, 255], rounds s to an
// integer in the low bits as std::nearbyint does, and loops of it vectorize (the fill routines'
// to_unorm8 is the same).
inline uint8_t to_unorm8(float v) {
  const float s = clamp01(v) * 255.f + 8388608.f;
  uint32_t bits;
  std::memcpy(&bits, &s, sizeof bits);
  return static_cast<uint8_t>(bits - 0x4b000000u);
}

// An RGBA colour as the RGBA8 word (R in the lowest byte) the fragment routines store for it.
inline uint32_t to_rgba8_word(const float rgba[4]) {
  uint32_t word = 0;
  for (int c = 0; c < 4; ++c) word |= uint32_t{to_unorm8(rgba[c])} << (8 * c);
  return word;
}

inline float blend_factor(BlendFactor f, int channel, const float src[4], const float dst[4], const float constant[4]) {
  switch (f) {
    case BlendFactor::Zero: return 0.f;
    case BlendFactor::One: return 1.f;
    case BlendFactor::SrcColor: return src[channel];
    case BlendFactor::OneMinusSrcColor: return 1.f - src[channel];
    case BlendFactor::DstColor: return dst[channel];
    case BlendFactor::OneMinusDstColor: return 1.f - dst[channel];
    case BlendFactor::SrcAlpha: return src[3];
    case BlendFactor::OneMinusSrcAlpha: return 1.f - src[3];
    case BlendFactor::DstAlpha: return dst[3];
    case BlendFactor::OneMinusDstAlpha: return 1.f - dst[3];
    case BlendFactor::ConstantColor: return constant[channel];
    case BlendFactor::OneMinusConstantColor: return 1.f - constant[channel];
    case BlendFactor::ConstantAlpha: return constant[3];
    case BlendFactor::OneMinusConstantAlpha: return 1.f - constant[3];
    case BlendFactor::SrcAlphaSaturate: return channel == 3 ? 1.f : std::min(src[3], 1.f - dst[3]);
  }
  return 0.f;
}

inline float blend_equation(BlendEquation eq, float s, float sf, float d, float df) {
  switch (eq) {
    case BlendEquation::Add: return s * sf + d * df;
    case BlendEquation::Subtract: return s * sf - d * df;
    case BlendEquation::ReverseSubtract: return d * df - s * sf;
    case BlendEquation::Min: return std::min(s, d);
    case BlendEquation::Max: return std::max(s, d);
  }
  return s;
}

inline uint8_t logic_op(LogicOp op, uint8_t s, uint8_t d) {
  unsigned r = 0;
  switch (op) {
    case LogicOp::Clear: r = 0; break;
    case LogicOp::And: r = s & d; break;
    case LogicOp::AndReverse: r = s & ~d; break;
    case LogicOp::Copy: r = s; break;
    case LogicOp::AndInverted: r = ~s & d; break;
    case LogicOp::Noop: r = d; break;
    case LogicOp::Xor: r = s ^ d; break;
    case LogicOp::Or: r = s | d; break;
    case LogicOp::Nor: r = ~(s | d); break;
    case LogicOp::Equiv: r = ~(s ^ d); break;
    case LogicOp::Invert: r = ~d; break;
    case LogicOp::OrReverse: r = s | ~d; break;
    case LogicOp::CopyInverted: r = ~s; break;
    case LogicOp::OrInverted: r = ~s | d; break;
    case LogicOp::Nand: r = ~(s & d); break;
    case LogicOp::Set: r = 0xff; break;
  }
  return static_cast<uint8_t>(r);
}

}  // namespace pineda::raster
