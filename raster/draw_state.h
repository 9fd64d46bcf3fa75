// The validated state one draw needs, as plain values: the "draw snapshot".
// raster/ knows no GL enums; state/ translates them into these.
#pragma once
#include <array>
#include <cstdint>
#include <memory>

#include "raster/framebuffer.h"
#include "raster/point_size.h"
#include "raster/sample_counter.h"
#include "raster/texture.h"

namespace pineda::raster {

struct ShaderDraw;  // raster/shader_draw.h

enum class StencilOp : uint8_t { Keep, Zero, Replace, Incr, Decr, Invert, IncrWrap, DecrWrap };
enum class BlendFactor : uint8_t {
  Zero, One, SrcColor, OneMinusSrcColor, DstColor, OneMinusDstColor, SrcAlpha, OneMinusSrcAlpha,
  DstAlpha, OneMinusDstAlpha, ConstantColor, OneMinusConstantColor, ConstantAlpha,
  OneMinusConstantAlpha, SrcAlphaSaturate
};
enum class BlendEquation : uint8_t { Add, Subtract, ReverseSubtract, Min, Max };
enum class LogicOp : uint8_t {
  Clear, And, AndReverse, Copy, AndInverted, Noop, Xor, Or, Nor, Equiv, Invert, OrReverse,
  CopyInverted, OrInverted, Nand, Set
};
enum class PolygonMode : uint8_t { Point, Line, Fill };
enum class Primitive : uint8_t {
  Points, Lines, LineLoop, LineStrip, Triangles, TriangleStrip, TriangleFan, Quads, QuadStrip, Polygon
};

struct Viewport {
  int x = 0, y = 0, width = 0, height = 0;
  double near_z = 0.0, far_z = 1.0;  // glDepthRange, clamped to [0, 1]
};

struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
};

struct StencilFace {
  CompareFunc func = CompareFunc::Always;
  int ref = 0;
  uint8_t value_mask = 0xff;
  uint8_t write_mask = 0xff;
  StencilOp fail = StencilOp::Keep, depth_fail = StencilOp::Keep, depth_pass = StencilOp::Keep;
};

// A draw buffer's factors and equations (ARB_draw_buffers_blend gives each its own).
struct BlendFunction {
  BlendFactor src_rgb = BlendFactor::One, dst_rgb = BlendFactor::Zero;
  BlendFactor src_alpha = BlendFactor::One, dst_alpha = BlendFactor::Zero;
  BlendEquation eq_rgb = BlendEquation::Add, eq_alpha = BlendEquation::Add;
};

struct BlendState : BlendFunction {
  float color[4] = {0, 0, 0, 0};  // one for every draw buffer
};

enum class FogMode : uint8_t { Linear, Exp, Exp2 };

// GL 1.5 section 3.10: f from the fragment's fog coordinate c, then C = f * C + (1 - f) * Cf.
struct Fog {
  bool enabled = false;
  FogMode mode = FogMode::Exp;
  float density = 1.f, start = 0.f, end = 1.f;
  float color[4] = {0, 0, 0, 0};
};

struct LineStipple {
  bool enabled = false;
  int factor = 1;            // clamped to [1, 256]
  uint16_t pattern = 0xffff;  // bit 0 first
};

// The 32x32 window-aligned polygon stipple: bit (x % 32) of row (y % 32), bit 0 = leftmost.
struct PolygonStipple {
  bool enabled = false;
  std::array<uint32_t, 32> rows = [] {
    std::array<uint32_t, 32> all_set;
    all_set.fill(~0u);
    return all_set;
  }();
};

// GL 1.5 sections 3.2.1 and 4.1.3: how a draw's fragments cover the samples of a multisampled
// framebuffer. Single-sampled framebuffers ignore it.
struct MultisampleState {
  bool multisample = true;  // GL_MULTISAMPLE: off, every sample takes the pixel centre's coverage
  bool alpha_to_coverage = false, alpha_to_one = false, sample_coverage = false;
  float coverage_value = 1.f;
  bool coverage_invert = false;
};

struct DrawState {
  Viewport viewport;
  bool scissor_test = false;
  Rect scissor;

  // Primitive processing
  bool cull_face = false;
  bool cull_front = false, cull_back = true;  // glCullFace
  bool front_ccw = true;                       // glFrontFace
  PolygonMode polygon_front = PolygonMode::Fill, polygon_back = PolygonMode::Fill;
  bool offset_fill = false, offset_line = false, offset_point = false;
  float offset_factor = 0.f, offset_units = 0.f;
  float point_size = 1.f;
  PointParameters point_params;  // with attenuation, the size comes per vertex (ClipVertex::point_size)
  float line_width = 1.f;
  bool point_smooth = false, line_smooth = false;  // antialiased: coverage multiplies alpha
  bool flat_shading = false;  // GL_FLAT: the provoking vertex's colour for the whole primitive
  uint32_t clip_planes = 0;   // bit i: user clip plane i enabled (ClipVertex::clip_distance[i])
  LineStipple line_stipple;
  PolygonStipple polygon_stipple;

  // Per-fragment stages, in pipeline order
  bool alpha_test = false;
  CompareFunc alpha_func = CompareFunc::Always;
  float alpha_ref = 0.f;
  bool stencil_test = false;
  StencilFace stencil_front, stencil_back;
  bool depth_test = false;
  CompareFunc depth_func = CompareFunc::Less;
  bool depth_write = true;
  bool blend = false;
  BlendState blend_state;
  bool logic_op_enabled = false;
  LogicOp logic_op = LogicOp::Copy;
  bool dither = true;  // accepted; Pineda never dithers (exact output)
  std::array<bool, 4> color_write = {true, true, true, true};
  // EXT_draw_buffers2 and ARB_draw_buffers_blend: the blend enable, colour write mask, blend
  // factors and equations of draw buffers 1.. (`blend`, `color_write` and `blend_state` above
  // are draw buffer 0's).
  struct TargetWrite {
    bool blend = false;
    std::array<bool, 4> color_write = {true, true, true, true};
    BlendFunction blend_function;
  };
  std::array<TargetWrite, kMaxColorTargets - 1> more_targets{};
  MultisampleState multisample;

  // Texturing; a unit is enabled when its image is non-null. Fixed function reads the first
  // kMaxTextureUnits, shaders all texture image units.
  std::array<TextureUnit, kMaxTextureImageUnits> texture_units;

  // Set while an occlusion query is active: the draw counts its passing samples here.
  std::shared_ptr<SampleCounter> sample_counter;

  // After texturing: the colour sum (ClipVertex::secondary added), then fog.
  bool color_sum = false;
  Fog fog;

  // A draw with a fragment and vertex program (null: fixed function). The vertex stage ran in
  // state/; raster/ interpolates its varyings and runs the fragment shader.
  std::shared_ptr<const ShaderDraw> shader;

  // Draw buffer i's blend enable, colour write mask and blend function become `blend`,
  // `color_write` and `blend_state`'s, the ones a draw's write stage reads.
  void use_target_write(int i) {
    if (i <= 0 || i >= kMaxColorTargets) return;
    const TargetWrite& t = more_targets[static_cast<size_t>(i - 1)];
    blend = t.blend;
    color_write = t.color_write;
    static_cast<BlendFunction&>(blend_state) = t.blend_function;
  }
};

// What glClear needs.
struct ClearState {
  bool color = false, depth = false, stencil = false;
  float color_value[4] = {0, 0, 0, 0};
  double depth_value = 1.0;
  int stencil_value = 0;
  std::array<bool, 4> color_write = {true, true, true, true};  // draw buffer 0's
  std::array<std::array<bool, 4>, kMaxColorTargets - 1> more_color_write = [] {  // draw buffers 1..
    std::array<std::array<bool, 4>, kMaxColorTargets - 1> all;
    all.fill({true, true, true, true});
    return all;
  }();
  uint8_t stencil_write_mask = 0xff;
  bool depth_write = true;
  bool scissor_test = false;
  Rect scissor;

  const std::array<bool, 4>& color_write_of(int draw_buffer) const {
    if (draw_buffer <= 0 || draw_buffer >= kMaxColorTargets) return color_write;
    return more_color_write[static_cast<size_t>(draw_buffer - 1)];
  }
};

}  // namespace pineda::raster
