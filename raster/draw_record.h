// A draw as the scene keeps it: a copy of the DrawState plus what is derived from it once
// per draw (the specialization key's routine, clamped reference values).
#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "raster/blend8.h"
#include "raster/draw_state.h"
#include "raster/fast_samplers.h"
#include "raster/framebuffer.h"
#include "raster/prim_setup.h"
#include "raster/sample_quad_tests.h"
#include "raster/sample_targets.h"
#include "raster/sampler_bilinear8.h"

namespace pineda::raster {

struct DrawRecord;

// Shades a row of `count` 2x2 quads, quad k at (x + 2k, y) (even coordinates); bit i of
// masks[k] is pixel (x + 2k + (i & 1), y + (i >> 1)). Returns the number of pixels that
// passed the depth test when the key counts samples, 0 otherwise.
using QuadRoutine = uint32_t (*)(const DrawRecord&, const PrimSetup&, const Framebuffer&, int x, int y, int count,
                             const uint8_t* masks);

// The compile-time part of the fragment pipeline: each combination has its own routine.
struct FragmentKey {
  bool textured = false;
  bool depth = false;
  bool stencil = false;
  bool blend = false;  // blending or logic op: the destination colour is read
  Blend8 blend8 = Blend8::Other;  // blending done in unorm8 integers (blend8.h); Other with a logic op
  bool flat = false;
  bool extras = false;  // colour sum, fog or a stipple: the routine checks which
  bool count_samples = false;  // an occlusion query is active
};

struct DrawRecord {
  DrawState state;
  FragmentKey key;
  QuadRoutine routine = nullptr;

  int num_units = 0;
  std::array<uint8_t, kMaxTextureUnits> units{};  // enabled texture units, in order
  std::array<uint8_t, kMaxTextureUnits> tex_plane{};  // first plane (s, t, q) of each enabled unit, in order
  std::array<int8_t, kMaxTextureUnits> r_plane{-1, -1, -1, -1};  // its r plane, -1 when not read
  std::array<QuadSampler, kMaxTextureUnits> fast_sampler{};  // of each enabled unit, in order; null: sample_quad
  // A programmable draw: each texture image unit's samplers for its 2D lookups (shader_textures.h).
  std::array<FastSamplers, kMaxTextureImageUnits> shader_samplers{};
  // A programmable draw: what the per-block steps (shader_quads.cpp) ask of its program, read
  // once here instead of by a virtual call per block (up to 2% of glsl_sprites).
  struct ShaderFacts {
    int varying_floats = 0;
    int draw_buffers_written = 0;
    unsigned frag_coord_components = 0;
    bool reads_point_coord = false;
    bool broadcasts_color = false;
    bool writes_depth = false;
    bool uses_discard = false;
  } shader_facts;
  // One unit, its fast sampler (bilinear or nearest), MODULATE or REPLACE of a texture whose
  // format's colour is RGB or L and alpha A, I or none: the quad is textured in lanes, channel by
  // channel (a luminance texture's texels hold L in R, G and B; an intensity one's in all four).
  bool texture_in_lanes = false;
  bool replaces_in_lanes = false;  // REPLACE: the texel's channels replace the fragment's
  bool bilinear_in_lanes = false;  // the fast sampler is the bilinear one (sampler_bilinear8.h)
  int modulated_channels = 4;  // 3: the texture has no alpha, the fragment's stays
  // bilinear_in_lanes without mipmaps (LINEAR minification): no level of detail, so the fill
  // routines sample whole rows of 8 pixels (bilinear8_lanes.inc) instead of quads.
  bool sample_rows = false;
  // texture_in_lanes by the nearest sampler with REPEAT or CLAMP(_TO_EDGE) wraps: the fill
  // routines take whole rows' texels (nearest8_lanes.inc) instead of quads'.
  bool nearest_rows = false;
  int planes = kColorPlanes;                      // interpolated planes
  int secondary_plane = -1;                       // first secondary colour plane, -1 when unused
  int fog_plane = -1;                             // the fog coordinate's plane, -1 when unused

  double depth_max = 0.0;  // 2^bits - 1
  float alpha_ref = 0.f;
  float blend_color[4] = {0, 0, 0, 0};
  uint8_t stencil_ref[2] = {0, 0};  // front, back
  bool color_write_any = true;
  bool color_write_all = true;
  // Multisampled framebuffers only (raster/multisample.h): the samples the draw may cover, and
  // one record per sample when they differ (alpha to coverage), else null.
  uint32_t sample_mask = ~0u;
  std::shared_ptr<const std::vector<DrawRecord>> sample_draws;
  // Multisampled framebuffers: shades each pixel once for all samples (null: the draw runs
  // `routine` once per sample plane).
  SampleQuadRoutine sample_routine = nullptr;
  // With a sample_routine: its stencil and depth tests over every sample of a quad (null
  // without either test).
  SampleQuadTests sample_tests = nullptr;
  // A sample's record under alpha to coverage: its sample is kept where alpha >= this too,
  // besides the application's alpha test (state.alpha_test is on, ALWAYS when GL's is off).
  bool alpha_to_coverage = false;
  float coverage_alpha_min = 0.f;
  // GL_SAMPLE_ALPHA_TO_ONE on a multisampled draw: alpha is 1 after the alpha test (key.extras).
  bool alpha_to_one = false;
  // Multisampled points of the draw may fade (SamplePoint::fade, applied with key.extras).
  bool fades_points = false;
  // Several draw buffers (Framebuffer::color_targets > 1): one record per draw buffer, each
  // specialized for its colour buffer; `routine` then runs them all (draw_targets.h).
  std::shared_ptr<const std::vector<DrawRecord>> target_draws;
};

// Leaves out of `units` the images make_draw_record would not sample (an empty or short level),
// as it does for the record's own units.
void drop_unusable_textures(std::array<TextureUnit, kMaxTextureImageUnits>& units);

// `path`: which copy of the fragment routine and samplers runs; `fades_points`: may_fade_points
// (multisample.h).
DrawRecord make_draw_record(const DrawState& state, const Framebuffer& fb, SimdPath path = SimdPath::Best,
                            bool fades_points = false);

}  // namespace pineda::raster
