// Each fragment stage with exact pixel values: alpha test, stencil, depth, blending,
// logic ops, write masks, formats.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/raster/test_support.h"

namespace pineda::raster::test {
namespace {

constexpr int kS = 4;

struct Target {
  explicit Target(int depth_bits = 24, ColorFormat format = ColorFormat::RGBA8) : fb(kS, kS, depth_bits, true, format) {
    r.set_framebuffer(fb.fb);
  }
  void clear(const float rgba[4], double depth = 1.0, int stencil = 0) {
    ClearState c;
    c.color = c.depth = c.stencil = true;
    for (int i = 0; i < 4; ++i) c.color_value[i] = rgba[i];
    c.depth_value = depth;
    c.stencil_value = stencil;
    r.clear(c);
    r.flush();
  }
  // A full-screen quad of one colour at NDC depth z; `cw` draws it clockwise (back-facing).
  void quad(const DrawState& s, const float rgba[4], float z = 0.f, bool cw = false) {
    std::vector<ClipVertex> v{vertex(-1, -1, z), vertex(1, -1, z), vertex(1, 1, z), vertex(-1, 1, z)};
    if (cw) std::swap(v[1], v[3]);
    for (auto& p : v)
      for (int i = 0; i < 4; ++i) p.color[i] = p.back_color[i] = rgba[i];
    r.draw(s, Primitive::Quads, v);
    r.flush();
  }
  const uint8_t* px() const { return fb.pixel(1, 2); }
  OwnedFramebuffer fb;
  Renderer r{1};
};

DrawState base() { return state_for(kS, kS); }

TEST(Fragment, ColourIsRoundedToNearest) {
  Target t;
  const float c[4] = {0.5f, 1.f / 255.f * 0.49f, 0.998f, 0.3f};
  t.quad(base(), c);
  EXPECT_EQ(t.px()[0], 128);  // 127.5: ties go to even
  EXPECT_EQ(t.px()[1], 0);
  EXPECT_EQ(t.px()[2], 254);  // 254.49
  EXPECT_EQ(t.px()[3], 76);   // 76.5: ties go to even
}

TEST(Fragment, Bgra8StoresBlueFirst) {
  Target t(24, ColorFormat::BGRA8);
  const float c[4] = {1.f, 0.5f, 0.f, 0.2f};
  t.quad(base(), c);
  EXPECT_EQ(t.px()[0], 0);
  EXPECT_EQ(t.px()[1], 128);
  EXPECT_EQ(t.px()[2], 255);
  EXPECT_EQ(t.px()[3], 51);
}

TEST(Fragment, AlphaTestAllFunctions) {
  const CompareFunc funcs[] = {CompareFunc::Never, CompareFunc::Less, CompareFunc::Equal, CompareFunc::LessEqual,
                               CompareFunc::Greater, CompareFunc::NotEqual, CompareFunc::GreaterEqual,
                               CompareFunc::Always};
  // alpha 0.5 against refs below, equal to and above it
  const bool expect[8][3] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, {0, 1, 1}, {1, 0, 0}, {1, 0, 1}, {1, 1, 0}, {1, 1, 1}};
  const float refs[3] = {0.25f, 0.5f, 0.75f};
  for (int f = 0; f < 8; ++f)
    for (int k = 0; k < 3; ++k) {
      Target t;
      const float black[4] = {0, 0, 0, 0}, c[4] = {1, 1, 1, 0.5f};
      t.clear(black);
      DrawState s = base();
      s.alpha_test = true;
      s.alpha_func = funcs[f];
      s.alpha_ref = refs[k];
      t.quad(s, c);
      EXPECT_EQ(t.px()[0] == 255, expect[f][k]) << f << " " << k;
    }
}

TEST(Fragment, DepthFunctionsAndPrecision) {
  const CompareFunc funcs[] = {CompareFunc::Never, CompareFunc::Less, CompareFunc::Equal, CompareFunc::LessEqual,
                               CompareFunc::Greater, CompareFunc::NotEqual, CompareFunc::GreaterEqual,
                               CompareFunc::Always};
  // Buffer cleared to 0.5; fragments at window depth 0.25, 0.5, 0.75 (NDC -0.5, 0, 0.5).
  const bool expect[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  const float ndc[3] = {-0.5f, 0.f, 0.5f};
  for (const int bits : {16, 24, 32}) {
    const double max = bits == 32 ? 4294967295.0 : std::ldexp(1.0, bits) - 1;
    for (int f = 0; f < 8; ++f)
      for (int k = 0; k < 3; ++k) {
        Target t(bits);
        const float black[4] = {0, 0, 0, 0}, c[4] = {1, 1, 1, 1};
        t.clear(black, 0.5);
        ASSERT_EQ(t.fb.depth_at(1, 2), static_cast<uint32_t>(0.5 * max + 0.5));
        DrawState s = base();
        s.depth_test = true;
        s.depth_func = funcs[f];
        t.quad(s, c, ndc[k]);
        EXPECT_EQ(t.px()[0] == 255, expect[f][k]) << bits << " " << f << " " << k;
        const double written = expect[f][k] ? (ndc[k] + 1) / 2 : 0.5;
        EXPECT_EQ(t.fb.depth_at(1, 2), static_cast<uint32_t>(written * max + 0.5)) << bits << " " << f << " " << k;
      }
  }
}

TEST(Fragment, DepthWriteMaskAndDisabledTestLeaveBufferAlone) {
  Target t;
  const float c[4] = {1, 1, 1, 1};
  t.clear(c, 1.0);
  DrawState s = base();
  s.depth_test = true;
  s.depth_write = false;
  t.quad(s, c, 0.f);
  EXPECT_EQ(t.fb.depth_at(1, 2), 0xffffffu);
  s.depth_test = false;
  s.depth_write = true;
  t.quad(s, c, 0.f);
  EXPECT_EQ(t.fb.depth_at(1, 2), 0xffffffu);
}

TEST(Fragment, DepthIsLinearInWindowSpace) {
  // A quad from NDC z -1 (left) to +1 (right) with 16-bit depth: the value at pixel column x
  // is the plane evaluated at the pixel centre.
  OwnedFramebuffer fb(64, 1, 16);
  Renderer r(1);
  r.set_framebuffer(fb.fb);
  clear_all(r);
  DrawState s = state_for(64, 1);
  s.depth_test = true;
  s.depth_func = CompareFunc::Always;
  r.draw(s, Primitive::Quads, std::vector<ClipVertex>{vertex(-1, -1, -1), vertex(1, -1, 1), vertex(1, 1, 1), vertex(-1, 1, -1)});
  r.flush();
  for (int x = 0; x < 64; ++x) EXPECT_EQ(fb.depth_at(x, 0), static_cast<uint32_t>((x + 0.5) / 64 * 65535 + 0.5)) << x;
}

TEST(Fragment, PolygonOffsetUnitsMoveByTwoDepthSteps) {
  Target t(16);
  const float c[4] = {1, 1, 1, 1};
  t.clear(c);
  DrawState s = base();
  s.depth_test = true;
  s.depth_func = CompareFunc::Always;
  s.offset_fill = true;
  s.offset_units = 3.f;
  s.offset_factor = 10.f;  // flat polygon: no slope
  t.quad(s, c, 0.f);
  EXPECT_EQ(t.fb.depth_at(1, 2), 32767u + 2 * 3 + 1);  // 0.5 * 65535 rounded up, one unit is two steps
}

struct StencilCase {
  StencilOp op;
  uint8_t before;
  uint8_t after;
};

TEST(Fragment, StencilOpsIncludingWrap) {
  const StencilCase cases[] = {
      {StencilOp::Keep, 7, 7},      {StencilOp::Zero, 7, 0},        {StencilOp::Replace, 7, 0x5a},
      {StencilOp::Incr, 7, 8},      {StencilOp::Incr, 255, 255},    {StencilOp::Decr, 7, 6},
      {StencilOp::Decr, 0, 0},      {StencilOp::Invert, 0x0f, 0xf0}, {StencilOp::IncrWrap, 255, 0},
      {StencilOp::DecrWrap, 0, 255}};
  for (const StencilCase& c : cases)
    for (int which = 0; which < 3; ++which) {  // fail, depth fail, depth pass
      Target t;
      const float black[4] = {0, 0, 0, 0}, white[4] = {1, 1, 1, 1};
      t.clear(black, 0.5, c.before);
      DrawState s = base();
      s.stencil_test = true;
      s.depth_test = true;
      s.stencil_front.ref = 0x5a;
      s.stencil_front.func = which == 0 ? CompareFunc::Never : CompareFunc::Always;
      s.stencil_front.fail = which == 0 ? c.op : StencilOp::Keep;
      s.stencil_front.depth_fail = which == 1 ? c.op : StencilOp::Keep;
      s.stencil_front.depth_pass = which == 2 ? c.op : StencilOp::Keep;
      t.quad(s, white, which == 1 ? 0.5f : -0.5f);
      EXPECT_EQ(t.fb.stencil_at(1, 2), c.after) << static_cast<int>(c.op) << " " << which;
      EXPECT_EQ(t.px()[0], which == 2 ? 255 : 0);
    }
}

TEST(Fragment, StencilMasksAndBackFaces) {
  Target t;
  const float black[4] = {0, 0, 0, 0}, white[4] = {1, 1, 1, 1};
  t.clear(black, 1.0, 0xf3);
  DrawState s = base();
  s.stencil_test = true;
  s.stencil_front.func = CompareFunc::Never;  // front faces would be rejected
  s.stencil_back.func = CompareFunc::Equal;
  s.stencil_back.ref = 0x13;
  s.stencil_back.value_mask = 0x0f;  // 0x03 == 0x03
  s.stencil_back.write_mask = 0x3c;
  s.stencil_back.depth_pass = StencilOp::Invert;  // ~0xf3 = 0x0c; masked: (0xf3 & ~0x3c) | (0x0c & 0x3c)
  t.quad(s, white, 0.f, /*cw=*/true);
  EXPECT_EQ(t.px()[0], 255);
  EXPECT_EQ(t.fb.stencil_at(1, 2), (0xf3 & ~0x3c) | (0x0c & 0x3c));
}

struct BlendCase {
  BlendFactor src, dst;
  BlendEquation eq;
  float expect_r;  // in [0,1], before rounding
};

TEST(Fragment, BlendFactorsAndEquations) {
  // src = (0.6, 0.2, 0.4, 0.3) is converted to unorm8 before blending (153, 51, 102, 76: ties
  // go to even); dst = (0.4, 0.8, 0.2, 0.5) is stored as (102, 204, 51, 128); constant =
  // (0.1, 0.2, 0.3, 0.4).
  const float src[4] = {0.6f, 0.2f, 0.4f, 0.3f};
  const float dst_in[4] = {0.4f, 0.8f, 0.2f, 0.5f};
  const float s_r = 153 / 255.f, s_a = 76 / 255.f, d_r = 102 / 255.f, d_a = 128 / 255.f;
  const BlendCase cases[] = {
      {BlendFactor::One, BlendFactor::Zero, BlendEquation::Add, s_r},
      {BlendFactor::Zero, BlendFactor::One, BlendEquation::Add, d_r},
      {BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha, BlendEquation::Add, s_r * s_a + d_r * (1 - s_a)},
      {BlendFactor::SrcColor, BlendFactor::OneMinusSrcColor, BlendEquation::Add, s_r * s_r + d_r * (1 - s_r)},
      {BlendFactor::DstColor, BlendFactor::OneMinusDstColor, BlendEquation::Add, s_r * d_r + d_r * (1 - d_r)},
      {BlendFactor::DstAlpha, BlendFactor::OneMinusDstAlpha, BlendEquation::Add, s_r * d_a + d_r * (1 - d_a)},
      {BlendFactor::ConstantColor, BlendFactor::OneMinusConstantColor, BlendEquation::Add, s_r * 0.1f + d_r * 0.9f},
      {BlendFactor::ConstantAlpha, BlendFactor::OneMinusConstantAlpha, BlendEquation::Add, s_r * 0.4f + d_r * 0.6f},
      {BlendFactor::SrcAlphaSaturate, BlendFactor::One, BlendEquation::Add, s_r * std::min(s_a, 1 - d_a) + d_r},
      {BlendFactor::One, BlendFactor::One, BlendEquation::Subtract, s_r - d_r},
      {BlendFactor::One, BlendFactor::One, BlendEquation::ReverseSubtract, 0.f},
      {BlendFactor::Zero, BlendFactor::Zero, BlendEquation::Min, d_r},
      {BlendFactor::Zero, BlendFactor::Zero, BlendEquation::Max, s_r},
      {BlendFactor::One, BlendFactor::One, BlendEquation::Add, 1.f},
  };
  for (const BlendCase& c : cases) {
    Target t;
    t.clear(dst_in);
    DrawState s = base();
    s.blend = true;
    s.blend_state.src_rgb = c.src;
    s.blend_state.dst_rgb = c.dst;
    s.blend_state.eq_rgb = c.eq;
    const float k[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    for (int i = 0; i < 4; ++i) s.blend_state.color[i] = k[i];
    t.quad(s, src);
    EXPECT_EQ(t.px()[0], static_cast<int>(std::nearbyint(c.expect_r * 255))) << static_cast<int>(c.src) << " "
                                                                                << static_cast<int>(c.dst);
    EXPECT_EQ(t.px()[3], 76);  // alpha: One, Zero, Add -> 0.3
  }
}

TEST(Fragment, SeparateAlphaBlend) {
  Target t;
  const float dst[4] = {0.f, 0.f, 0.f, 1.f}, src[4] = {1.f, 1.f, 1.f, 0.5f};
  t.clear(dst);
  DrawState s = base();
  s.blend = true;
  s.blend_state.src_rgb = BlendFactor::SrcAlpha;
  s.blend_state.dst_rgb = BlendFactor::Zero;
  s.blend_state.src_alpha = BlendFactor::Zero;
  s.blend_state.dst_alpha = BlendFactor::DstAlpha;
  t.quad(s, src);
  EXPECT_EQ(t.px()[0], 128);
  EXPECT_EQ(t.px()[3], 255);
}

TEST(Fragment, AllSixteenLogicOps) {
  const uint8_t s = 0xcc & 0xff, d = 0xaa;  // src 204/255, dst 170/255
  const uint8_t expect[16] = {0x00,           static_cast<uint8_t>(s & d),    static_cast<uint8_t>(s & ~d),
                              s,              static_cast<uint8_t>(~s & d),   d,
                              static_cast<uint8_t>(s ^ d),  static_cast<uint8_t>(s | d),  static_cast<uint8_t>(~(s | d)),
                              static_cast<uint8_t>(~(s ^ d)), static_cast<uint8_t>(~d), static_cast<uint8_t>(s | ~d),
                              static_cast<uint8_t>(~s),     static_cast<uint8_t>(~s | d), static_cast<uint8_t>(~(s & d)),
                              0xff};
  for (int op = 0; op < 16; ++op) {
    Target t;
    const float dst[4] = {d / 255.f, d / 255.f, d / 255.f, d / 255.f};
    const float src[4] = {s / 255.f, s / 255.f, s / 255.f, s / 255.f};
    t.clear(dst);
    DrawState st = base();
    st.logic_op_enabled = true;
    st.blend = true;  // ignored: the logic op replaces blending
    st.blend_state.src_rgb = BlendFactor::Zero;
    st.logic_op = static_cast<LogicOp>(op);
    t.quad(st, src);
    EXPECT_EQ(t.px()[0], expect[op]) << op;
    EXPECT_EQ(t.px()[3], expect[op]) << op;
  }
}

TEST(Fragment, ColourWriteMask) {
  Target t;
  const float dst[4] = {0.2f, 0.2f, 0.2f, 0.2f}, src[4] = {1, 1, 1, 1};
  t.clear(dst);
  DrawState s = base();
  s.color_write = {true, false, true, false};
  t.quad(s, src);
  EXPECT_EQ(t.px()[0], 255);
  EXPECT_EQ(t.px()[1], 51);
  EXPECT_EQ(t.px()[2], 255);
  EXPECT_EQ(t.px()[3], 51);
}

TEST(Fragment, ClearHonoursScissorAndMasks) {
  Target t;
  const float a[4] = {0.2f, 0.2f, 0.2f, 0.2f};
  t.clear(a, 1.0, 0);
  ClearState c;
  c.color = c.stencil = c.depth = true;
  c.color_value[0] = c.color_value[1] = 1.f;
  c.color_write = {true, false, true, true};
  c.stencil_value = 0xff;
  c.stencil_write_mask = 0x0f;
  c.depth_value = 0.0;
  c.scissor_test = true;
  c.scissor = {1, 1, 2, 2};
  t.r.clear(c);
  t.r.flush();
  EXPECT_EQ(t.fb.pixel(1, 2)[0], 255);
  EXPECT_EQ(t.fb.pixel(1, 2)[1], 51);
  EXPECT_EQ(t.fb.pixel(1, 2)[2], 0);
  EXPECT_EQ(t.fb.stencil_at(1, 2), 0x0f);
  EXPECT_EQ(t.fb.depth_at(1, 2), 0u);
  EXPECT_EQ(t.fb.pixel(0, 0)[0], 51);
  EXPECT_EQ(t.fb.pixel(3, 3)[0], 51);
  EXPECT_EQ(t.fb.depth_at(3, 3), 0xffffffu);
}

TEST(Fragment, NegativeStrideIsTopDownMemory) {
  std::vector<uint8_t> mem(kS * kS * 4, 0);
  Framebuffer fb;
  fb.width = fb.height = kS;
  fb.color = {mem.data() + (kS - 1) * kS * 4, -kS * 4, ColorFormat::RGBA8, {}, 0};
  Renderer r(1);
  r.set_framebuffer(fb);
  // The bottom row only (window y in [0, 1)).
  r.draw(base(), Primitive::Quads,
         std::vector<ClipVertex>{vertex(-1, -1), vertex(1, -1), vertex(1, -0.5f), vertex(-1, -0.5f)});
  r.flush();
  EXPECT_EQ(mem[(kS - 1) * kS * 4], 255);  // last row in memory
  EXPECT_EQ(mem[0], 0);
}

}  // namespace
}  // namespace pineda::raster::test
