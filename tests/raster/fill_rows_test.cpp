// The fill routines (raster/fill_rows.cpp) against the generic quad routines: the same colour
// depth and stencil buffers and sample counts, bit for bit, on every SIMD copy, for random
// triangles over odd-sized framebuffers, with depth functions, stencil functions and operations
// (front and back faces), blending (over and the two additive blends), colour masks, flat and
// perspective colours, both colour orders, and MODULATE or REPLACE of an RGBA, RGB, luminance,
// luminance-alpha or intensity texture (bilinear, mipmapped or not, or nearest).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "raster/fill_rows.h"
#include "raster/fragment_pipeline.h"
#include "raster/raster_limits.h"
#include "raster/setup.h"
#include "raster/tile_raster.h"
#include "tests/raster/test_support.h"

namespace pineda::raster {
namespace {

struct Config {
  bool depth = true;
  CompareFunc func = CompareFunc::Less;
  bool depth_write = true;
  bool blend = false;
  BlendFactor blend_src = BlendFactor::SrcAlpha, blend_dst = BlendFactor::OneMinusSrcAlpha;
  bool flat = false;
  bool one_color = false;  // smooth shading, every vertex of a triangle the same colour
  bool perspective = false;
  bool mask_alpha = false;  // colour mask without alpha
  bool count = false;
  ColorFormat format = ColorFormat::RGBA8;
  bool stencil = false;
  StencilFace front, back;  // back: every other triangle faces back
  bool textured = false;  // unit 0: MODULATE (or `env`), bilinear (or nearest)
  TexEnvMode env = TexEnvMode::Modulate;
  bool nearest = false;  // NEAREST minification and magnification (not mipmapped)
  TexWrap wrap_s = TexWrap::Repeat, wrap_t = TexWrap::ClampToEdge;
  bool mipmapped = false;
  TexFilter mip_filter = TexFilter::LinearMipmapLinear;  // the minification filter when mipmapped
  TexBaseFormat texture_format = TexBaseFormat::RGBA;
  // Level 0's sides when not mipmapped; pixel_mapped: about one texel per pixel (0.5 to 1.9,
  // and exactly one on every other triangle, as in a copy of the framebuffer) anywhere on it.
  int texture_width = 16, texture_height = 16;
  bool pixel_mapped = false;
  // Texture coordinates far outside the texture (1e30, 1e10), q through zero (inf and NaN
  // quotients) and NaN attributes on some triangles.
  bool wild_coordinates = false;
};

// A random texel as a texture of the format stores it (texture_format.cpp's reduction: L in R, G
// and B, I in all four), but for a random alpha where the format has none (which MODULATE
// must not read).
uint32_t random_texel(TexBaseFormat format, std::mt19937& rng) {
  const uint32_t v = rng(), l = v & 0xffu, a = v >> 24;
  switch (format) {
    case TexBaseFormat::RGB: return v;
    case TexBaseFormat::Luminance: return l * 0x010101u | a << 24;
    case TexBaseFormat::LuminanceAlpha: return l * 0x010101u | a << 24;
    case TexBaseFormat::Intensity: return l * 0x01010101u;
    case TexBaseFormat::Alpha: return a << 24;
    case TexBaseFormat::RGBA: break;
  }
  return v;
}

std::shared_ptr<const TextureImage> random_texture(const Config& c) {
  std::mt19937 rng(11);
  auto image = std::make_shared<TextureImage>();
  image->base_format = c.texture_format;
  if (!c.mipmapped) {
    TextureLevel level{c.texture_width, c.texture_height, {}};
    for (int i = 0; i < c.texture_width * c.texture_height; ++i) level.texels.edit().push_back(random_texel(c.texture_format, rng));
    image->levels.push_back(std::move(level));
    return image;
  }
  for (int size = 16; size >= 1; size /= 2) {
    TextureLevel level{size, size, {}};
    for (int i = 0; i < size * size; ++i) level.texels.edit().push_back(random_texel(c.texture_format, rng));
    image->levels.push_back(std::move(level));
  }
  return image;
}

struct Buffers {
  std::vector<uint8_t> color;
  std::vector<uint32_t> depth;
  std::vector<uint8_t> stencil;
  uint64_t passed = 0;
};

std::vector<PrimSetup> random_triangles(const Config& c, int w, int h, std::mt19937& rng) {
  std::uniform_real_distribution<double> px(-8.0, w + 8.0), py(-8.0, h + 8.0), size(1.0, 40.0), unit(0.0, 1.0);
  std::vector<PrimSetup> prims;
  SetupParams params;
  params.clip = {0, 0, w, h};
  params.flat = c.flat;
  params.planes = c.textured ? kColorPlanes + kTexPlanesPerUnit : kColorPlanes;
  while (prims.size() < 60) {
    WinVert v[3];
    // Texels per pixel and where the pixel (0, 0) lands on the texture, for pixel_mapped.
    double scale = 1.0, s0 = 0.0, t0 = 0.0;
    if (c.pixel_mapped) {
      scale = prims.size() % 2 ? 1.0 : 0.5 + unit(rng) * 1.4;
      s0 = std::floor(unit(rng) * c.texture_width * 1.2) - 0.1 * c.texture_width;
      t0 = std::floor(unit(rng) * c.texture_height * 1.2) - 0.1 * c.texture_height;
    }
    // Small and large triangles: a centre, then vertices around it.
    const double cx = px(rng), cy = py(rng), r = prims.size() % 3 == 0 ? size(rng) * 4.0 : size(rng);
    for (WinVert& vert : v) {
      vert.fx = cx + (unit(rng) - 0.5) * 2.0 * r;
      vert.fy = cy + (unit(rng) - 0.5) * 2.0 * r;
      vert.x = static_cast<int64_t>(std::llround(vert.fx * kSubpixelOne));
      vert.y = static_cast<int64_t>(std::llround(vert.fy * kSubpixelOne));
      vert.z = unit(rng) * 16777215.0;
      vert.inv_w = c.perspective ? 0.2 + unit(rng) : 1.0;
      for (int k = 0; k < 4; ++k) vert.attr[k] = static_cast<float>(unit(rng) * 1.2 - 0.1);
      // s, t, q: a few repeats of the texture across a triangle, q near 1
      for (int k = 4; k < 6; ++k) vert.attr[k] = static_cast<float>(unit(rng) * 5.0 - 2.0);
      vert.attr[6] = static_cast<float>(0.5 + unit(rng));
      if (c.wild_coordinates) {
        static constexpr float kWild[] = {1e30f, -1e30f, 1e10f, -3e9f, 0.f, -0.f, 7.5f};
        const size_t kind = prims.size() % 4;
        for (int k = 4; k < 6; ++k) vert.attr[k] = kWild[rng() % std::size(kWild)];
        if (kind == 1) vert.attr[6] = static_cast<float>(unit(rng) - 0.5);  // q changes sign inside
        if (kind == 2) vert.attr[4 + rng() % 3] = std::numeric_limits<float>::quiet_NaN();
        if (kind == 3) vert.attr[6] = 0.f;
      }
      if (c.pixel_mapped) {
        vert.attr[4] = static_cast<float>((s0 + vert.fx * scale) / c.texture_width);
        vert.attr[5] = static_cast<float>((t0 + vert.fy * scale) / c.texture_height);
        vert.attr[6] = 1.f;
      }
    }
    if (c.one_color)
      for (int k = 0; k < 4; ++k) v[1].attr[k] = v[2].attr[k] = v[0].attr[k];
    for (int k = 0; k < 4; ++k) params.flat_color[k] = v[2].attr[k];
    params.back_facing = prims.size() % 2 == 1;
    PrimSetup prim;
    if (setup_triangle(v[0], v[1], v[2], params, prim)) prims.push_back(prim);
  }
  return prims;
}

Buffers render(const Config& c, const std::vector<PrimSetup>& prims, int w, int h, SimdPath path, bool generic) {
  test::OwnedFramebuffer target(w, h, 24, c.stencil, c.format);
  std::mt19937 fill(7);
  for (uint8_t& b : target.color) b = static_cast<uint8_t>(fill());
  for (uint32_t& z : target.depth) z = fill() & 0xffffff;
  // Small values, so that the comparisons with small references go both ways; and the ends.
  for (uint8_t& v : target.stencil_buf) v = static_cast<uint8_t>(fill() % 5 == 0 ? 255 : fill() % 4);
  DrawState s = test::state_for(w, h);
  s.depth_test = c.depth;
  s.depth_func = c.func;
  s.depth_write = c.depth_write;
  s.blend = c.blend;
  s.blend_state.src_rgb = s.blend_state.src_alpha = c.blend_src;
  s.blend_state.dst_rgb = s.blend_state.dst_alpha = c.blend_dst;
  s.flat_shading = c.flat;
  if (c.mask_alpha) s.color_write[3] = false;
  if (c.count) s.sample_counter = std::make_shared<SampleCounter>();
  s.stencil_test = c.stencil;
  s.stencil_front = c.front;
  s.stencil_back = c.back;
  if (c.textured) {
    TextureUnit& unit = s.texture_units[0];
    unit.image = random_texture(c);
    unit.sampler.min_filter = c.mipmapped ? c.mip_filter : c.nearest ? TexFilter::Nearest : TexFilter::Linear;
    unit.sampler.mag_filter = c.nearest ? TexFilter::Nearest : TexFilter::Linear;
    unit.env_mode = c.env;
    unit.sampler.wrap_s = c.wrap_s;
    unit.sampler.wrap_t = c.wrap_t;
  }
  DrawRecord d = make_draw_record(s, target.fb, path);
  EXPECT_EQ(d.sample_rows, c.textured && !c.mipmapped && !c.nearest);
  const QuadRoutine fill_routine = select_fill_routine(d, target.fb, path);
  EXPECT_NE(fill_routine, nullptr);
  EXPECT_EQ(d.routine, fill_routine) << "make_draw_record takes the fill routine";
  if (generic) {  // the texture environment pixel by pixel too (apply_unit_env)
    d.routine = select_quad_routine(d.key, SimdPath::Baseline);
    d.texture_in_lanes = false;
  }
  Buffers out;
  for (const PrimSetup& prim : prims)
    for (int ty = 0; ty < h; ty += kTileSize)
      for (int tx = 0; tx < w; tx += kTileSize)
        out.passed += rasterize_in_tile(prim, d, target.fb, {tx, ty, std::min(tx + kTileSize, w), std::min(ty + kTileSize, h)});
  out.color = target.color;
  out.depth = target.depth;
  out.stencil = target.stencil_buf;
  return out;
}

void expect_same_as_generic(const Config& c, const std::string& name) {
  for (const auto& [w, h] : {std::pair{77, 53}, std::pair{150, 97}}) {
    std::mt19937 rng(w * 1000 + h);
    const std::vector<PrimSetup> prims = random_triangles(c, w, h, rng);
    const Buffers generic = render(c, prims, w, h, SimdPath::Baseline, true);
    for (const SimdPath path : {SimdPath::Best, SimdPath::Avx2, SimdPath::Baseline}) {
      const Buffers fill = render(c, prims, w, h, path, false);
      int color_diff = 0, depth_diff = 0, stencil_diff = 0;
      for (size_t i = 0; i < fill.color.size(); ++i) color_diff += fill.color[i] != generic.color[i];
      for (size_t i = 0; i < fill.depth.size(); ++i) depth_diff += fill.depth[i] != generic.depth[i];
      for (size_t i = 0; i < fill.stencil.size(); ++i) stencil_diff += fill.stencil[i] != generic.stencil[i];
      EXPECT_EQ(color_diff, 0) << name << " " << w << "x" << h << " path " << static_cast<int>(path);
      EXPECT_EQ(depth_diff, 0) << name << " " << w << "x" << h << " path " << static_cast<int>(path);
      EXPECT_EQ(stencil_diff, 0) << name << " " << w << "x" << h << " path " << static_cast<int>(path);
      EXPECT_EQ(fill.passed, generic.passed) << name;
    }
  }
}

TEST(FillRows, DepthFunctionsMatchTheGenericRoutine) {
  for (const CompareFunc f : {CompareFunc::Never, CompareFunc::Less, CompareFunc::Equal, CompareFunc::LessEqual,
                              CompareFunc::Greater, CompareFunc::NotEqual, CompareFunc::GreaterEqual,
                              CompareFunc::Always}) {
    Config c;
    c.func = f;
    expect_same_as_generic(c, "func " + std::to_string(static_cast<int>(f)));
  }
  Config no_write;
  no_write.depth_write = false;
  no_write.count = true;
  expect_same_as_generic(no_write, "no depth write, counted");
}

TEST(FillRows, ColoursMatchTheGenericRoutine) {
  Config c;
  expect_same_as_generic(c, "smooth");
  c.perspective = true;
  expect_same_as_generic(c, "perspective");
  c.flat = true;
  expect_same_as_generic(c, "flat");
  c = {};
  c.depth = false;
  c.count = true;
  expect_same_as_generic(c, "no depth, counted");
  c.format = ColorFormat::BGRA8;
  c.mask_alpha = true;
  expect_same_as_generic(c, "BGRA, alpha masked");
  // The colour made once per triangle (with values past 0 and 1 to clamp).
  c = {};
  c.one_color = true;
  expect_same_as_generic(c, "one colour");
  c.blend = true;
  c.format = ColorFormat::BGRA8;
  c.mask_alpha = true;
  expect_same_as_generic(c, "one colour, blend, BGRA, alpha masked");
  c.perspective = true;
  expect_same_as_generic(c, "one colour, perspective");
}

TEST(FillRows, BlendOverMatchesTheGenericRoutine) {
  Config c;
  c.blend = true;
  c.depth = false;
  expect_same_as_generic(c, "blend");
  c.mask_alpha = true;
  c.perspective = true;
  expect_same_as_generic(c, "blend, alpha masked, perspective");
  c.format = ColorFormat::BGRA8;
  c.depth = true;
  c.flat = true;
  expect_same_as_generic(c, "blend, BGRA, depth, flat");
}

// Every stencil function against reference 2 (value mask 3), and every operation in each of
// the three places, with and without depth, front and back faces differing.
TEST(FillRows, StencilMatchesTheGenericRoutine) {
  const StencilOp ops[] = {StencilOp::Keep,   StencilOp::Zero,   StencilOp::Replace,  StencilOp::Incr,
                           StencilOp::Decr,   StencilOp::Invert, StencilOp::IncrWrap, StencilOp::DecrWrap};
  for (int f = 0; f < 8; ++f) {
    Config c;
    c.stencil = true;
    c.front.func = static_cast<CompareFunc>(f);
    c.front.ref = 2;
    c.front.value_mask = 3;
    c.front.fail = StencilOp::Invert;
    c.front.depth_fail = StencilOp::Incr;
    c.front.depth_pass = StencilOp::Replace;
    c.back = c.front;
    c.back.func = static_cast<CompareFunc>(7 - f);
    c.back.ref = 1;
    c.back.write_mask = 0x0f;
    expect_same_as_generic(c, "stencil func " + std::to_string(f));
  }
  for (int k = 0; k < 8; ++k) {
    Config c;
    c.stencil = true;
    c.front.func = CompareFunc::GreaterEqual;
    c.front.ref = 2;
    c.front.fail = ops[k];
    c.front.depth_fail = ops[(k + 3) % 8];
    c.front.depth_pass = ops[(k + 5) % 8];
    c.back = c.front;
    c.back.func = CompareFunc::NotEqual;
    c.back.ref = 255;
    c.back.fail = ops[(k + 1) % 8];
    c.back.depth_pass = ops[(k + 6) % 8];
    c.back.write_mask = 0xf3;
    c.blend = k % 2 == 1;
    c.depth_write = k % 3 != 0;
    c.count = k % 4 == 2;
    expect_same_as_generic(c, "stencil ops " + std::to_string(k));
    c.depth = false;
    expect_same_as_generic(c, "stencil ops, no depth " + std::to_string(k));
  }
}

// expect_same_as_generic for each pair of the wrap modes the fill routines sample in lanes.
void expect_same_as_generic_each_wrap(const Config& c, const std::string& name) {
  for (const TexWrap s : {TexWrap::Repeat, TexWrap::ClampToEdge})
    for (const TexWrap t : {TexWrap::Repeat, TexWrap::ClampToEdge}) {
      Config w = c;
      w.wrap_s = s;
      w.wrap_t = t;
      expect_same_as_generic(w, name + ", wrap " + std::to_string(static_cast<int>(s)) + "/" + std::to_string(static_cast<int>(t)));
    }
}

TEST(FillRows, ModulatedTexturesMatchTheGenericRoutine) {
  Config c;
  c.textured = true;
  expect_same_as_generic(c, "textured");
  c.perspective = true;
  // Without mipmaps the routines sample rows of 8 (DrawRecord::sample_rows).
  expect_same_as_generic_each_wrap(c, "textured rows");
  // Mipmapped: rows of 8 where a group's quads read the same levels, quads elsewhere.
  c.mipmapped = true;
  expect_same_as_generic(c, "textured, mipmapped, perspective");
  for (const TexFilter min : {TexFilter::LinearMipmapLinear, TexFilter::LinearMipmapNearest}) {
    Config m = c;
    m.mip_filter = min;
    expect_same_as_generic_each_wrap(m, "mipmapped, filter " + std::to_string(static_cast<int>(min)));
  }
  c.texture_format = TexBaseFormat::RGB;
  c.blend = true;
  c.depth = false;
  expect_same_as_generic(c, "RGB texture, blend");
  c.flat = true;
  c.format = ColorFormat::BGRA8;
  c.mask_alpha = true;
  c.depth = true;
  expect_same_as_generic(c, "textured, flat, BGRA, alpha masked");
}

// NEAREST filtering (the nearest sampler per quad) and REPLACE, of every base format the fill
// routines take.
TEST(FillRows, NearestAndReplacedTexturesMatchTheGenericRoutine) {
  Config c;
  c.textured = true;
  c.nearest = true;
  c.perspective = true;
  expect_same_as_generic_each_wrap(c, "nearest");
  // Rows of 8 for REPEAT and CLAMP(_TO_EDGE) (DrawRecord::nearest_rows), quads for MIRRORED_REPEAT.
  for (const TexWrap wrap : {TexWrap::MirroredRepeat, TexWrap::Clamp}) {
    Config w = c;
    w.wrap_s = wrap;
    expect_same_as_generic(w, "nearest, wrap " + std::to_string(static_cast<int>(wrap)));
  }
  Config wild = c;
  wild.wild_coordinates = true;
  expect_same_as_generic_each_wrap(wild, "nearest, wild coordinates");
  Config mapped = c;  // texel centres near pixel centres, as a copy of the framebuffer
  mapped.pixel_mapped = true;
  mapped.texture_width = 64;
  mapped.texture_height = 32;
  expect_same_as_generic_each_wrap(mapped, "nearest, pixel mapped");
  c.env = TexEnvMode::Replace;
  expect_same_as_generic_each_wrap(c, "nearest, replace");
  c.nearest = false;
  expect_same_as_generic(c, "bilinear rows, replace");
  c.mipmapped = true;
  expect_same_as_generic(c, "mipmapped, replace");
  c.mipmapped = false;
  c.nearest = true;
  for (const TexBaseFormat format : {TexBaseFormat::RGB, TexBaseFormat::Luminance, TexBaseFormat::LuminanceAlpha,
                                     TexBaseFormat::Intensity}) {
    c.texture_format = format;
    c.blend = format == TexBaseFormat::LuminanceAlpha;
    expect_same_as_generic(c, "nearest, replace, format " + std::to_string(static_cast<int>(format)));
  }
  c.flat = true;
  c.format = ColorFormat::BGRA8;
  c.mask_alpha = true;
  expect_same_as_generic(c, "nearest, replace, flat, BGRA, alpha masked");
  // RGBA texels replacing all four channels are written as their words (red and blue exchanged
  // for a BGRA target), blended and masked as any colour.
  Config words;
  words.textured = words.nearest = words.perspective = true;
  words.env = TexEnvMode::Replace;
  words.format = ColorFormat::BGRA8;
  expect_same_as_generic_each_wrap(words, "nearest, replace, RGBA into BGRA");
  words.blend = true;
  words.mask_alpha = true;
  expect_same_as_generic(words, "nearest, replace, RGBA into BGRA, blended, alpha masked");
  words.format = ColorFormat::RGBA8;
  words.blend_src = words.blend_dst = BlendFactor::One;
  expect_same_as_generic(words, "nearest, replace, RGBA, added");
  words.wild_coordinates = true;
  words.blend = words.mask_alpha = false;
  expect_same_as_generic_each_wrap(words, "nearest, replace, RGBA, wild coordinates");
}

// Coordinates no texture lookup can honour still read defined texels, the same on every path.
TEST(FillRows, WildTextureCoordinatesMatchTheGenericRoutine) {
  Config c;
  c.textured = true;
  c.wild_coordinates = true;
  c.perspective = true;
  expect_same_as_generic_each_wrap(c, "wild coordinates, rows");
  c.mipmapped = true;
  expect_same_as_generic_each_wrap(c, "wild coordinates, mipmapped");
}

// SRC_ALPHA / ONE and ONE / ONE, untextured and MODULATEd (a luminance texture: glblur's blur).
TEST(FillRows, AdditiveBlendsMatchTheGenericRoutine) {
  for (const BlendFactor src : {BlendFactor::SrcAlpha, BlendFactor::One}) {
    const std::string name = src == BlendFactor::One ? "add" : "add scaled";
    Config additive;
    additive.blend = true;
    additive.blend_src = src;
    additive.blend_dst = BlendFactor::One;
    additive.depth = false;
    Config c = additive;
    expect_same_as_generic(c, name);
    c.depth = true;
    c.flat = true;
    c.format = ColorFormat::BGRA8;
    c.mask_alpha = true;
    expect_same_as_generic(c, name + ", depth, flat, BGRA, alpha masked");
    c.flat = false;
    c.one_color = true;
    expect_same_as_generic(c, name + ", one colour");
    c = additive;
    c.textured = true;
    c.texture_format = TexBaseFormat::Luminance;
    c.perspective = true;
    expect_same_as_generic_each_wrap(c, name + ", luminance texture");
    c.mipmapped = true;
    c.depth = true;
    c.texture_format = TexBaseFormat::RGBA;
    expect_same_as_generic(c, name + ", mipmapped RGBA texture, depth");
  }
}

// Luminance, luminance-alpha and intensity textures multiply channel by channel too.
TEST(FillRows, LuminanceAndIntensityTexturesMatchTheGenericRoutine) {
  for (const TexBaseFormat format : {TexBaseFormat::Luminance, TexBaseFormat::LuminanceAlpha, TexBaseFormat::Intensity}) {
    const std::string name = "format " + std::to_string(static_cast<int>(format));
    Config c;
    c.textured = true;
    c.texture_format = format;
    c.perspective = true;
    expect_same_as_generic(c, name);
    c.mipmapped = true;
    c.blend = true;
    c.depth = false;
    expect_same_as_generic(c, name + ", mipmapped, blend");
  }
}

// A level of 2^18 texels or more, about a texel per pixel: the AVX-512 rows read it through a
// window of 16 columns by 2 rows (bilinear8_lanes.inc) where the row fits, near its right and top
// edges too, and gather elsewhere (a repeat's wrap, steep minification).
TEST(FillRows, PixelMappedLargeTexturesMatchTheGenericRoutine) {
  Config c;
  c.textured = true;
  c.pixel_mapped = true;
  c.texture_width = 520;
  c.texture_height = 510;
  c.blend = true;
  c.depth = false;
  expect_same_as_generic_each_wrap(c, "pixel mapped, blend");
  c.texture_width = 1030;
  c.texture_height = 257;
  c.blend = false;
  c.depth = true;
  c.texture_format = TexBaseFormat::RGB;
  expect_same_as_generic_each_wrap(c, "pixel mapped, wide, RGB");
}

TEST(FillRows, OtherKeysTakeTheGenericRoutine) {
  test::OwnedFramebuffer target(8, 8);
  DrawState s = test::state_for(8, 8);
  s.alpha_test = true;
  EXPECT_EQ(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s = test::state_for(8, 8);
  s.blend = true;  // ONE, ZERO: not SRC_ALPHA, ONE_MINUS_SRC_ALPHA
  EXPECT_EQ(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s = test::state_for(8, 8);
  s.texture_units[0].image = random_texture(Config{});
  s.texture_units[0].sampler.min_filter = TexFilter::Linear;  // the fast sampler's
  s.texture_units[0].env_mode = TexEnvMode::Decal;  // only MODULATE and REPLACE
  EXPECT_EQ(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s.texture_units[0].env_mode = TexEnvMode::Replace;
  EXPECT_NE(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s.texture_units[0].sampler.mag_filter = TexFilter::Nearest;  // no fast sampler: LINEAR and NEAREST mixed
  EXPECT_EQ(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s.texture_units[0].sampler.min_filter = TexFilter::Nearest;  // the nearest sampler
  EXPECT_NE(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s.texture_units[0].sampler.min_filter = TexFilter::Linear;
  s.texture_units[0].sampler.mag_filter = TexFilter::Linear;
  s.texture_units[0].env_mode = TexEnvMode::Modulate;
  s.stencil_test = true;  // textured: not with stencil
  EXPECT_EQ(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s.stencil_test = false;
  EXPECT_NE(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  Config alpha;
  alpha.texture_format = TexBaseFormat::Alpha;  // texels 0, 0, 0, A: MODULATE leaves the colour
  s.texture_units[0].image = random_texture(alpha);
  EXPECT_EQ(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  auto swizzled = std::make_shared<TextureImage>(*random_texture(Config{}));
  swizzled->env_format = TexBaseFormat::Luminance;  // the environment reads R only, texels RGBA
  s.texture_units[0].image = swizzled;
  EXPECT_EQ(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  swizzled->env_format = TexBaseFormat::RGB;
  EXPECT_NE(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s = test::state_for(8, 8);
  s.blend = true;
  s.blend_state.src_rgb = s.blend_state.src_alpha = BlendFactor::SrcAlpha;
  s.blend_state.dst_rgb = s.blend_state.dst_alpha = BlendFactor::One;
  EXPECT_NE(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s.stencil_test = true;  // additive: not with stencil
  EXPECT_EQ(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s.stencil_test = false;
  s.blend_state.dst_rgb = BlendFactor::OneMinusSrcAlpha;
  s.blend_state.src_alpha = BlendFactor::Zero;  // colour over, alpha kept: the shader path's writers only
  EXPECT_EQ(make_draw_record(s, target.fb).key.blend8, Blend8::OverKeepAlpha);
  EXPECT_EQ(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  s = test::state_for(8, 8);
  s.fog.enabled = true;
  EXPECT_EQ(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
  test::OwnedFramebuffer deep(8, 8, 32);
  s = test::state_for(8, 8);
  s.depth_test = true;
  EXPECT_EQ(select_fill_routine(make_draw_record(s, deep.fb), deep.fb), nullptr);
  s = test::state_for(8, 8);
  EXPECT_NE(select_fill_routine(make_draw_record(s, target.fb), target.fb), nullptr);
}

}  // namespace
}  // namespace pineda::raster
