#include "raster/draw_record.h"

#include <algorithm>

#include "raster/blend8.h"
#include "raster/draw_targets.h"
#include "raster/fill_rows.h"
#include "raster/fragment_pipeline.h"
#include "raster/sample_quads.h"
#include "raster/sampler_nearest8.h"
#include "raster/shader_draw.h"
#include "raster/shader_quads.h"

namespace pineda::raster {
namespace {

float clamp01(float v) { return v > 0.f ? (v < 1.f ? v : 1.f) : 0.f; }

// A texture the sampler can read without bounds checks: every level non-empty and complete.
bool texture_usable(const TextureImage* image) {
  if (!image || image->levels.empty()) return false;
  for (const TextureLevel& l : image->levels) {
    if (l.width <= 0 || l.height <= 0) return false;
    if (l.depth <= 0 || (image->kind == TexKind::Cube && l.depth != 6)) return false;
    if (l.texels.size() < static_cast<size_t>(l.width) * static_cast<size_t>(l.height) * static_cast<size_t>(l.depth))
      return false;
  }
  return true;
}

uint8_t stencil_ref(int ref) { return static_cast<uint8_t>(std::clamp(ref, 0, 255)); }

}  // namespace

void drop_unusable_textures(std::array<TextureUnit, kMaxTextureImageUnits>& units) {
  for (int u = 0; u < kMaxTextureUnits; ++u)
    if (units[u].image && !texture_usable(units[u].image.get())) units[u].image.reset();
}

DrawRecord make_draw_record(const DrawState& draw_state, const Framebuffer& fb, SimdPath path, bool fades_points) {
  DrawRecord d;
  d.state = draw_state;
  d.state.use_target_write(fb.color_index);
  const DrawState& state = d.state;
  drop_unusable_textures(d.state.texture_units);
  for (int u = 0; u < kMaxTextureUnits; ++u)
    if (d.state.texture_units[u].image) d.units[d.num_units++] = static_cast<uint8_t>(u);
  bool bilinear_first = false;  // unit 0 samples with select_bilinear8_sampler
  bool fast_first = false;      // ... or with select_nearest8_sampler
  d.planes = kColorPlanes;
  for (int k = 0; k < d.num_units; ++k) {
    d.tex_plane[k] = static_cast<uint8_t>(d.planes);
    const TextureUnit& unit = d.state.texture_units[d.units[k]];
    d.fast_sampler[k] = select_bilinear8_sampler(*unit.image, unit.sampler, path);
    if (k == 0) bilinear_first = d.fast_sampler[0] != nullptr;
    if (!d.fast_sampler[k]) d.fast_sampler[k] = select_nearest8_sampler(*unit.image, unit.sampler);
    if (k == 0) fast_first = d.fast_sampler[0] != nullptr;
    d.planes += kTexPlanesPerUnit;
    if (!d.state.texture_units[d.units[k]].reads_r()) continue;
    d.r_plane[k] = static_cast<int8_t>(d.planes);
    d.planes += kTexRPlanes;
  }
  if (d.num_units == 1) {
    const TextureUnit& unit = d.state.texture_units[d.units[0]];
    const TexBaseFormat format = unit.image->texenv_format();
    // Luminance and intensity multiply or replace channel by channel only as their own texels (a
    // swizzled texture's are RGBA); ALPHA's texels (0, 0, 0, A) never do. (REPLACE of the
    // channels a format has is MODULATE's selection of them: apply_tex_env.)
    const bool rgb = format == TexBaseFormat::RGBA || format == TexBaseFormat::RGB;
    const bool in_lanes_env = unit.env_mode == TexEnvMode::Modulate || unit.env_mode == TexEnvMode::Replace;
    d.texture_in_lanes = fast_first && in_lanes_env &&
                         (rgb || (format == unit.image->base_format && format != TexBaseFormat::Alpha));
    d.replaces_in_lanes = d.texture_in_lanes && unit.env_mode == TexEnvMode::Replace;
    d.bilinear_in_lanes = d.texture_in_lanes && bilinear_first;
    d.modulated_channels = format == TexBaseFormat::RGB || format == TexBaseFormat::Luminance ? 3 : 4;
    // (The fill routines' row samplers filter bilinearly.)
    d.sample_rows = d.bilinear_in_lanes && unit.sampler.min_filter == TexFilter::Linear;
    auto row_wrap = [](TexWrap w) { return w == TexWrap::Repeat || w == TexWrap::ClampToEdge || w == TexWrap::Clamp; };
    d.nearest_rows = d.texture_in_lanes && !bilinear_first && row_wrap(unit.sampler.wrap_s) && row_wrap(unit.sampler.wrap_t);
  }
  if (state.color_sum) {
    d.secondary_plane = d.planes;
    d.planes += kSecondaryPlanes;
  }
  if (state.fog.enabled) {
    d.fog_plane = d.planes;
    d.planes += kFogPlanes;
  }

  const bool has_depth = fb.depth.base && fb.depth.bits > 0;
  const bool has_stencil = fb.stencil.base && fb.stencil.bits > 0;
  d.depth_max = fb.depth.bits >= 32 ? 4294967295.0 : static_cast<double>((uint64_t{1} << std::max(fb.depth.bits, 1)) - 1);
  d.alpha_ref = clamp01(state.alpha_ref);
  for (int i = 0; i < 4; ++i) d.blend_color[i] = clamp01(state.blend_state.color[i]);
  d.stencil_ref[0] = stencil_ref(state.stencil_front.ref);
  d.stencil_ref[1] = stencil_ref(state.stencil_back.ref);
  d.color_write_any = std::any_of(state.color_write.begin(), state.color_write.end(), [](bool b) { return b; });

  d.color_write_all = std::all_of(state.color_write.begin(), state.color_write.end(), [](bool b) { return b; });

  d.key.textured = d.num_units > 0;
  d.key.depth = state.depth_test && has_depth;
  d.key.stencil = state.stencil_test && has_stencil;
  d.key.blend = state.blend || state.logic_op_enabled;
  d.key.blend8 = state.blend && !state.logic_op_enabled ? blend8_of(state.blend_state) : Blend8::Other;
  d.key.flat = state.flat_shading;
  d.key.extras = state.color_sum || state.fog.enabled || state.line_stipple.enabled || state.polygon_stipple.enabled ||
                 state.point_smooth || state.line_smooth;
  d.key.count_samples = state.sample_counter != nullptr;
  // GL 1.5 4.1.3: with multisampling on for the draw, alpha becomes 1 after alpha to coverage.
  d.alpha_to_one = fb.samples > 1 && state.multisample.multisample && state.multisample.alpha_to_one;
  d.key.extras |= d.alpha_to_one;
  d.fades_points = fades_points;
  d.key.extras |= fades_points;
  d.routine = select_quad_routine(d.key, path);
  const QuadRoutine fill = select_fill_routine(d, fb, path);
  if (fill) d.routine = fill;
  if (state.shader) {  // the fragment shader replaces texturing, the colour sum and fog
    d.planes = 0;
    d.secondary_plane = d.fog_plane = -1;
    d.texture_in_lanes = d.replaces_in_lanes = d.bilinear_in_lanes = d.sample_rows = d.nearest_rows = false;
    d.key.extras = state.line_stipple.enabled || state.polygon_stipple.enabled || state.point_smooth ||
                   state.line_smooth || fades_points;
    d.routine = shade_program_quads;
    if (const shader::Program* program = state.shader->program.get()) {
      d.shader_facts = {.varying_floats = program->varying_floats(),
                        .draw_buffers_written = program->draw_buffers_written(),
                        .frag_coord_components = program->frag_coord_components(),
                        .reads_point_coord = program->reads_point_coord(),
                        .broadcasts_color = program->broadcasts_color(),
                        .writes_depth = program->writes_depth(),
                        .uses_discard = program->uses_discard()};
    }
    for (size_t u = 0; u < state.texture_units.size(); ++u)
      if (const TextureUnit& unit = state.texture_units[u]; unit.image)
        d.shader_samplers[u] = choose_fast_samplers(*unit.image, unit.sampler, path);
  }
  // Multisampled: a fill routine (fill_rows.h) on each sample plane outruns one shading per
  // pixel followed by the generic quad operations per sample (2x2 quads, one lane per pixel), so
  // draws that have one keep the per-plane path; alpha to coverage gives them none.
  const bool alpha_to_coverage = state.multisample.multisample && state.multisample.alpha_to_coverage;
  if (fb.samples > 1 && (state.shader || !fill || alpha_to_coverage)) {
    d.sample_routine = state.shader ? shade_program_sample_quads : select_sample_quad_routine(d.key, path);
    d.sample_tests = select_sample_quad_tests(d.key, path);
  }
  if (fb.color_targets > 1) {
    prepare_target_draws(d, fb, path);
    if (state.shader) {
      d.routine = shade_program_target_quads;
      if (fb.samples > 1) d.sample_routine = shade_program_target_sample_quads;
    }
  }
  return d;
}

}  // namespace pineda::raster
