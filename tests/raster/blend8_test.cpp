// The integer blends (raster/blend8.h) against the generic routines' float blend (quad_ops.h's
// blend_quad on the unorm8 values, then to_unorm8) for every source value, alpha and
// destination value, and which blend states take them.
#include <gtest/gtest.h>

#include <cstdint>

#include "raster/blend8.h"
#include "raster/draw_record.h"
#include "raster/quad_ops.h"

namespace pineda::raster {
namespace {

DrawRecord blending(BlendFactor src, BlendFactor dst, BlendFactor src_alpha, BlendFactor dst_alpha) {
  DrawRecord d;
  d.state.blend_state.src_rgb = src;
  d.state.blend_state.src_alpha = src_alpha;
  d.state.blend_state.dst_rgb = dst;
  d.state.blend_state.dst_alpha = dst_alpha;
  return d;
}
DrawRecord blending(BlendFactor src, BlendFactor dst) { return blending(src, dst, src, dst); }

// Pixels whose channels 0-2 hold s, s ^ 0x5a, 255 - s and whose alpha is a, over a destination
// whose channels hold d, d ^ 0xa5, 255 - d, d: as the float path blends them, and as `integer`
// does, for every (s, a, d). Returns the number of pixels that differ.
template <typename Integer>
int differences(const DrawRecord& d, Integer integer) {
  int differ = 0;
  for (uint32_t a = 0; a < 256; ++a)
    for (uint32_t s = 0; s < 256; ++s)
      for (uint32_t t = 0; t < 256; t += 4) {
        U4 src, dst;
        for (uint32_t i = 0; i < 4; ++i) {
          src[i] = s | ((s ^ 0x5au) << 8) | ((255u - s) << 16) | (a << 24);
          const uint32_t v = t + i;
          dst[i] = v | ((v ^ 0xa5u) << 8) | ((255u - v) << 16) | (v << 24);
        }
        quad_ops::QuadColor from, to;
        for (int c = 0; c < 4; ++c) {
          from.c[c] = from_unorm8(src >> (8 * c));
          to.c[c] = from_unorm8(dst >> (8 * c));
        }
        const quad_ops::QuadColor out = quad_ops::blend_quad(d, from, to);
        U4 expected = {0, 0, 0, 0};
        for (int c = 0; c < 4; ++c) expected |= to_unorm8(out.c[c]) << (8 * c);
        const U4 got = integer(src, dst);
        for (int i = 0; i < 4; ++i) differ += got[i] != expected[i];
      }
  return differ;
}

TEST(Blend8, OverEqualsTheFloatBlendEverywhere) {
  EXPECT_EQ(differences(blending(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha),
                        [](U4 s, U4 d) { return blend_over8(s, d); }),
            0);
}

// The lanes' form (fill routines, shader block writes): two channels per 16-bit multiply.
TEST(Blend8, OverInHalvesEqualsTheFloatBlendEverywhere) {
  EXPECT_EQ(differences(blending(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha),
                        [](U4 s, U4 d) { return blend_over_halves(s, d); }),
            0);
}

TEST(Blend8, AddScaledEqualsTheFloatBlendEverywhere) {
  EXPECT_EQ(differences(blending(BlendFactor::SrcAlpha, BlendFactor::One),
                        [](U4 s, U4 d) { return blend_add_scaled8(s, d); }),
            0);
}

TEST(Blend8, AddEqualsTheFloatBlendEverywhere) {
  EXPECT_EQ(differences(blending(BlendFactor::One, BlendFactor::One), [](U4 s, U4 d) { return blend_add8(s, d); }), 0);
}

TEST(Blend8, OverKeepAlphaEqualsTheFloatBlendEverywhere) {
  EXPECT_EQ(differences(blending(BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha, BlendFactor::Zero, BlendFactor::One),
                        [](U4 s, U4 d) { return keep_alpha8(blend_over8(s, d), d); }),
            0);
}

TEST(Blend8, SaturatesAndRoundsAsExpected) {
  // 200 + 100 saturates; 128 * 255 / 255 = 128 exactly; 1 * 128 / 255 = 0.502 rounds to 1.
  EXPECT_EQ(blend_add8(U4{} + 0x00c80080u, U4{} + 0x00640001u)[0], 0x00ff0081u);
  EXPECT_EQ(blend_add_scaled8(U4{} + 0xff000080u, U4{} + 0x01000001u)[0], 0xff000081u);
  EXPECT_EQ(blend_add_scaled8(U4{} + 0x80000001u, U4{} + 0x00000000u)[0], 0x40000001u);
}

TEST(Blend8, OnlyTheirOwnStatesTakeThem) {
  BlendState b;
  b.src_rgb = b.src_alpha = BlendFactor::SrcAlpha;
  b.dst_rgb = b.dst_alpha = BlendFactor::One;
  EXPECT_EQ(blend8_of(b), Blend8::AddScaled);
  b.dst_rgb = b.dst_alpha = BlendFactor::OneMinusSrcAlpha;
  EXPECT_EQ(blend8_of(b), Blend8::Over);
  b.src_alpha = BlendFactor::Zero;
  b.dst_alpha = BlendFactor::One;
  EXPECT_EQ(blend8_of(b), Blend8::OverKeepAlpha);
  b.dst_alpha = BlendFactor::OneMinusSrcAlpha;
  b.src_rgb = b.src_alpha = BlendFactor::One;
  EXPECT_EQ(blend8_of(b), Blend8::Other);  // premultiplied over: float
  b.dst_rgb = b.dst_alpha = BlendFactor::One;
  EXPECT_EQ(blend8_of(b), Blend8::Add);
  b.dst_alpha = BlendFactor::Zero;  // separate alpha factors
  EXPECT_EQ(blend8_of(b), Blend8::Other);
  b.dst_alpha = BlendFactor::One;
  b.eq_alpha = BlendEquation::Max;
  EXPECT_EQ(blend8_of(b), Blend8::Other);
  b.eq_alpha = BlendEquation::Add;
  b.eq_rgb = BlendEquation::Subtract;
  EXPECT_EQ(blend8_of(b), Blend8::Other);
}

}  // namespace
}  // namespace pineda::raster
