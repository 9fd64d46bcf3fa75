#include "raster/shader_quads.h"

#include <algorithm>
#include <array>
#include <type_traits>

#include "raster/block_depth.h"
#include "raster/block_write.h"
#include "raster/fragment_extras.h"
#include "raster/fragment_ops.h"
#include "raster/quad_ops.h"
#include "raster/raster_limits.h"
#include "raster/shader_draw.h"
#include "raster/shader_textures.h"
#include "raster/varying_lanes.h"

namespace pineda::raster {
namespace {

using namespace quad_ops;
using shader::kLanes;

// Depth and stencil for the quad at (x, y) with window depths z (depth-buffer units); the
// same tests and updates as the fixed-function routines, one pixel at a time.
unsigned depth_stencil_lanes(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y,
                             unsigned mask, const uint32_t z[4]) {
  const DrawState& s = d.state;
  const StencilFace& face = p.back_facing ? s.stencil_back : s.stencil_front;
  const uint8_t ref = d.stencil_ref[p.back_facing ? 1 : 0];
  for (int i = 0; i < 4; ++i) {
    if (!(mask & (1u << i))) continue;
    const int px = x + (i & 1), py = y + (i >> 1);
    uint8_t* stencil = nullptr;
    uint8_t sv = 0;
    auto update_stencil = [&](StencilOp op) {
      const uint8_t nv = stencil_op(op, sv, ref);
      *stencil = static_cast<uint8_t>((sv & ~face.write_mask) | (nv & face.write_mask));
    };
    if (d.key.stencil) {
      stencil = fb.stencil.base + static_cast<ptrdiff_t>(py) * fb.stencil.stride + px;
      sv = *stencil;
      if (!compare(face.func, static_cast<uint8_t>(ref & face.value_mask), static_cast<uint8_t>(sv & face.value_mask))) {
        update_stencil(face.fail);
        mask &= ~(1u << i);
        continue;
      }
    }
    if (d.key.depth) {
      uint32_t* depth = fb.depth.base + static_cast<ptrdiff_t>(py) * fb.depth.stride + px;
      if (!compare(s.depth_func, z[i], *depth)) {
        if (d.key.stencil) update_stencil(face.depth_fail);
        mask &= ~(1u << i);
        continue;
      }
      if (s.depth_write) *depth = z[i];
    }
    if (d.key.stencil) update_stencil(face.depth_pass);
  }
  return mask;
}

// Window depth of the plane at the quad's pixels, as the fixed-function routines step it.
void plane_depths(const DrawRecord& d, const PrimSetup& p, F4 ox, F4 oy, uint32_t z[4]) {
  for (int i = 0; i < 4; ++i) {
    double v = p.z0 + p.dzdx * static_cast<double>(ox[i]) + p.dzdy * static_cast<double>(oy[i]);
    v = v > 0.0 ? (v < d.depth_max ? v : d.depth_max) : 0.0;
    z[i] = static_cast<uint32_t>(v + 0.5);
  }
}

[[gnu::always_inline]] inline void write_colors(const DrawRecord& d, const Framebuffer& fb, int x, int y, unsigned mask,
                                              const QuadColor& col) {
  if (!d.key.blend) write_quad<false, false>(d, fb, x, y, mask, col);
  else if (d.key.blend_over) write_quad<true, true>(d, fb, x, y, mask, col);
  else write_quad<true, false>(d, fb, x, y, mask, col);
}

struct Quad {
  int x = 0;
  unsigned mask = 0;
  F4 ox, oy;  // pixel centres relative to the primitive's reference point
};

// The draw buffers with a colour buffer and a colour to write, each as a single-target view,
// its gl_FragData index and its record (its blend enable and colour mask).
struct TargetViews {
  std::array<Framebuffer, kMaxColorTargets> view;
  std::array<int, kMaxColorTargets> output{};
  std::array<const DrawRecord*, kMaxColorTargets> record{};
  int count = 0;
};
struct NoTargets {};

// Up to four blocks of row y shaded together (shader::Program::run_fragment_blocks): each
// block's quads, its fragment inputs, and what it needs after the run.
struct RowBlocks {
  static constexpr int kMax = shader::kMaxBlocksPerRun;
  int count = 0;
  Quad quads[kMax][4];
  int quad_count[kMax] = {};
  shader::FragmentBlock blocks[kMax];
  alignas(64) float varyings[kMax][shader::kMaxVaryingFloats][kLanes];
};

bool early_tests(const DrawRecord& d, const shader::Program& program) {
  return (d.key.depth || d.key.stencil) && !program.writes_depth() && !program.uses_discard() && !d.state.alpha_test;
}

// Depth and stencil of the quad at (x, y) before shading (early_tests): its pixels that pass.
// Adds them to `passed` when the draw counts samples.
unsigned early_depth_stencil(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int y, const Quad& q,
                             unsigned mask, uint32_t& passed) {
  if (!d.key.stencil) {  // the fixed-function routines' depth test: the same depths and results
    mask = depth_only(d, p, fb, q.x, y, mask, q.ox, q.oy);
  } else {
    uint32_t plane_z[4];
    plane_depths(d, p, q.ox, q.oy, plane_z);
    mask = depth_stencil_lanes(d, p, fb, q.x, y, mask, plane_z);
  }
  if (d.key.count_samples) passed += static_cast<uint32_t>(__builtin_popcount(mask));
  return mask;
}

// The early tests of block k of `row` (early_tests): four adjacent quads inside the buffer and
// one tile without stencil at once (block_depth.h), others quad by quad.
void early_tests_of_block(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int y, RowBlocks& row, int k,
                          uint32_t& passed) {
  Quad* quads = row.quads[k];
  const int n = row.quad_count[k];
  const int x = quads[0].x;
  const bool adjacent = n == 4 && quads[1].x == x + 2 && quads[2].x == x + 4 && quads[3].x == x + 6;
  if (!d.key.stencil && adjacent && x >= 0 && x + 8 <= fb.width && y >= 0 && y + 2 <= fb.height &&
      (x & (kTileSize - 1)) + 8 <= kTileSize) {
    static const BlockDepthTest test = select_block_depth_test(simd_path_from_environment());
    alignas(64) float ox[kLanes], oy[kLanes];
    unsigned masks[4];
    for (int j = 0; j < 4; ++j) {
      store4(&ox[4 * j], quads[j].ox);
      store4(&oy[4 * j], quads[j].oy);
      masks[j] = quads[j].mask;
    }
    test(d, p, fb, x, y, ox, oy, masks);
    for (int j = 0; j < 4; ++j) {
      quads[j].mask = masks[j];
      if (d.key.count_samples) passed += static_cast<uint32_t>(__builtin_popcount(masks[j]));
    }
    return;
  }
  for (int q = 0; q < n; ++q) quads[q].mask = early_depth_stencil(d, p, fb, y, quads[q], quads[q].mask, passed);
}

// Fills block k of `row` for up to four quads of row y (after any early tests); returns false
// when no pixel is left to shade.
bool begin_block(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int y, const float* uniform_values,
                 RowBlocks& row, int k) {
  const ShaderDraw& sd = *d.state.shader;
  const shader::Program& program = *sd.program;
  const DrawState& s = d.state;
  Quad* quads = row.quads[k];
  const int n = row.quad_count[k];
  shader::FragmentBlock& block = row.blocks[k];
  block.live = 0;
  for (int q = 0; q < n; ++q) block.live |= static_cast<shader::LaneMask>(quads[q].mask << (4 * q));
  if (!block.live) return false;
  // The blend reads the block's pixels once the shader has run: fetching their lines now
  // overlaps the misses with the shading (glsl_sprites, one thread: 81 to 71 ms a frame).
  if (d.key.blend && fb.color.base) {
    const int x0 = quads[0].x, x1 = std::min(x0 + 7, fb.width - 1);  // x1: maybe on the next line
    __builtin_prefetch(color_address(fb, x0, y), 1);
    __builtin_prefetch(color_address(fb, x1, y), 1);
    if (block.live & 0xCCCCu) {  // else the row above may lie past the buffer
      __builtin_prefetch(color_address(fb, x0, y + 1), 1);
      __builtin_prefetch(color_address(fb, x1, y + 1), 1);
    }
  }

  const int nv = program.varying_floats();
  float (*varyings)[kLanes] = row.varyings[k];
  const float* point = p.kind == CoverageKind::Point && p.varying_planes ? &p.varying_planes[nv].a0 : nullptr;
  const unsigned frag_coord = program.frag_coord_components();
  alignas(64) float ox[kLanes], oy[kLanes], w[kLanes];
  for (int j = 0; j < 4; ++j) {
    const Quad& q = quads[j < n ? j : 0];  // unused lanes repeat quad 0: derivatives stay finite
    store4(&ox[4 * j], q.ox);
    store4(&oy[4 * j], q.oy);
  }
  static const VaryingInterpolator interpolate = select_varying_interpolator(simd_path_from_environment());
  interpolate(p.varying_planes, nv, p.inv_w, p.perspective, ox, oy, varyings, w);
  // Only the components the program reads (glmark2's conditionals, function and loop scenes read
  // gl_FragCoord.xy: the depth's per-lane doubles took half of begin_block there).
  if (frag_coord || point) {
    for (int j = 0; j < 4; ++j) {
      const Quad& q = quads[j < n ? j : 0];
      for (int i = 0; i < 4; ++i) {
        const int lane = 4 * j + i;
        const float fx = static_cast<float>(q.x + (i & 1)) + 0.5f, fy = static_cast<float>(y + (i >> 1)) + 0.5f;
        block.frag_coord[0][lane] = fx;
        block.frag_coord[1][lane] = fy;
        if (frag_coord & 4u) {
          double z = p.z0 + p.dzdx * static_cast<double>(q.ox[i]) + p.dzdy * static_cast<double>(q.oy[i]);
          z = z > 0.0 ? (z < d.depth_max ? z : d.depth_max) : 0.0;
          block.frag_coord[2][lane] = static_cast<float>(z / d.depth_max);
        }
        block.frag_coord[3][lane] = w[lane];
        if (point && point[2] > 0.f) {
          block.point_coord[0][lane] = 0.5f + (fx - point[0]) / point[2];
          block.point_coord[1][lane] = 0.5f - (fy - point[1]) / point[2];
        }
      }
    }
  }
  // Zeros where there is no sprite, for the programs that read them (filling them for every
  // block of every program took a fifth of begin_block).
  if (program.reads_point_coord() && !(point && point[2] > 0.f))
    std::fill(&block.point_coord[0][0], &block.point_coord[0][0] + 2 * kLanes, 0.f);
  // A colour buffer the program does not write reads as zeros.
  if (sd.color_output >= program.draw_buffers_written())
    std::fill(&block.color[sd.color_output][0][0], &block.color[sd.color_output][0][0] + 4 * kLanes, 0.f);
  if (sd.color_output != 0 && s.alpha_test)  // colour 0's alpha is tested even if never written
    std::fill(&block.color[0][3][0], &block.color[0][3][0] + kLanes, 0.f);
  if (!program.broadcasts_color())  // else colour 0 serves every draw buffer
    for (int i = program.draw_buffers_written(); i < fb.color_targets; ++i)
      std::fill(&block.color[i][0][0], &block.color[i][0][0] + 4 * kLanes, 0.f);
  block.varyings = &varyings[0][0];
  block.front_facing = p.back_facing ? 0 : 0xffff;
  block.run = 0xffff;  // the unused quads repeat quad 0
  block.uniform_values = uniform_values;
  block.denormals_flushed = true;  // a tile runs shader draws with them flushed (Scene::run_tile)
  return true;
}

// The alpha test of quad j of a shaded block (state.alpha_test on): its pixels of `mask` that
// pass. The alpha of colour 0 decides for every draw buffer (as in Mesa; GL 3.0 4.1.4).
unsigned alpha_test_quad(const DrawRecord& d, const PrimSetup& p, const shader::FragmentBlock& block, int j, int x,
                         int y, unsigned mask) {
  F4 alpha = load4(&block.color[0][3][4 * j]);
  if (d.key.extras) apply_coverage(p, x, y, alpha);
  for (int i = 0; i < 4; ++i)
    if (!alpha_passes(d, clamp01(alpha[i]))) mask &= ~(1u << i);
  return mask;
}

// gl_FragDepth of quad j of a shaded block in depth-buffer units.
void shader_depths(const DrawRecord& d, const shader::FragmentBlock& block, int j, uint32_t z[4]) {
  for (int i = 0; i < 4; ++i) {
    const float v = clamp01(block.depth[4 * j + i]);
    z[i] = static_cast<uint32_t>(static_cast<double>(v) * d.depth_max + 0.5);
  }
}

// Whether block k of the row is adjacent quads whose live pixels all get written, each wholly
// and in the same way (block_write.h): nothing but the colour and coverage is left to decide.
bool writes_block_lanes(const DrawRecord& d, const Framebuffer& fb, const RowBlocks& row, int k, bool no_late_tests,
                        bool write_color) {
  if (!write_color || !no_late_tests) return false;
  for (int j = 1; j < row.quad_count[k]; ++j)
    if (row.quads[k][j].x != row.quads[k][0].x + 2 * j) return false;
  const DrawState& s = d.state;
  return !d.key.extras && !s.alpha_test && !d.alpha_to_one && d.color_write_all && !fb.color.reduction.active &&
         (!d.key.blend || (d.key.blend_over && !s.logic_op_enabled));
}

// After the run: alpha test, late depth and stencil, colour writes of the `live` lanes of block
// k (the block's own live lanes, or a sample's: shade_sample_quads); returns the samples that
// passed a late depth test. `p` gives the depth; the colours are the block's.
template <bool kTargets>
uint32_t finish_block(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int y,
                      const std::conditional_t<kTargets, TargetViews, NoTargets>& targets, const RowBlocks& row, int k,
                      shader::LaneMask live_lanes, bool early) {
  const ShaderDraw& sd = *d.state.shader;
  const shader::Program& program = *sd.program;
  const DrawState& s = d.state;
  const shader::FragmentBlock& block = row.blocks[k];
  const bool tests = d.key.depth || d.key.stencil;
  bool write_color = fb.color.base && d.color_write_any;
  if constexpr (kTargets) write_color = targets.count > 0;
  uint32_t passed = 0;
  if constexpr (!kTargets) {
    if (writes_block_lanes(d, fb, row, k, early || !tests, write_color)) {
      static const BlockWriter write = select_block_writer(simd_path_from_environment());
      const Quad& q = row.quads[k][0];
      const auto live = static_cast<uint16_t>(live_lanes & ((1u << (4 * row.quad_count[k])) - 1u));
      // The writer touches the live pixels alone; without any in the second row, that row may
      // lie past the buffer, and is not addressed.
      uint8_t* const row0 = color_address(fb, q.x, y);
      uint8_t* const row1 = (live & 0xCCCCu) ? color_address(fb, q.x, y + 1) : row0;
      write(block.color[sd.color_output], fb.color.format == ColorFormat::BGRA8 ? kBgraShift.at : kRgbaShift.at,
            d.key.blend, row0, row1, live);
      return d.key.count_samples && !early ? static_cast<uint32_t>(__builtin_popcount(live)) : 0;
    }
  }
  for (int j = 0; j < row.quad_count[k]; ++j) {
    unsigned mask = (live_lanes >> (4 * j)) & 0xfu;
    if (!mask) continue;
    const Quad& q = row.quads[k][j];
    QuadColor col;
    for (int c = 0; c < 4; ++c) col.c[c] = load4(&block.color[sd.color_output][c][4 * j]);
    if (d.key.extras) apply_coverage(p, q.x, y, col.c[3]);
    if (s.alpha_test) mask = alpha_test_quad(d, p, block, j, q.x, y, mask);
    if (d.alpha_to_one) col.c[3] = splat(1.f);  // after alpha to coverage (the alpha test above)
    if (!early && tests) {
      uint32_t z[4];
      if (program.writes_depth()) shader_depths(d, block, j, z);
      else plane_depths(d, p, q.ox, q.oy, z);
      mask = depth_stencil_lanes(d, p, fb, q.x, y, mask, z);
    }
    if (d.key.count_samples && !early) passed += static_cast<uint32_t>(__builtin_popcount(mask));
    if (!mask || !write_color) continue;
    if constexpr (!kTargets) {
      write_colors(d, fb, q.x, y, mask, col);
    } else {
      for (int t = 0; t < targets.count; ++t) {
        QuadColor out;
        for (int c = 0; c < 4; ++c) out.c[c] = load4(&block.color[targets.output[size_t(t)]][c][4 * j]);
        if (d.key.extras) apply_coverage(p, q.x, y, out.c[3]);
        if (d.alpha_to_one) out.c[3] = splat(1.f);
        write_colors(*targets.record[size_t(t)], targets.view[size_t(t)], q.x, y, mask, out);
      }
    }
  }
  return passed;
}

// The quads of a row that `keep(q, quad, n)` keeps (quad n of the block being filled; false:
// no pixel of quad q to shade) in blocks of up to four: begin(k) fills block k (false: nothing
// left in it to shade), run() shades the blocks so far and empties the row.
template <class Keep, class Begin, class Run>
[[gnu::always_inline]] inline void group_quads(RowBlocks& row, int x, F4 ox0, F4 oy, int count, const Keep& keep,
                                               const Begin& begin, const Run& run) {
  int n = 0;
  for (int q = 0; q < count; ++q) {
    Quad& quad = row.quads[row.count][n];
    if (!keep(q, quad, n)) continue;
    quad.x = x + 2 * q;
    quad.ox = ox0 + splat(static_cast<float>(2 * q));
    quad.oy = oy;
    if (++n == 4 || q == count - 1) {
      row.quad_count[row.count] = n;
      if (begin(row.count)) ++row.count;
      n = 0;
      if (row.count == RowBlocks::kMax) run();
    }
  }
  if (n) {
    row.quad_count[row.count] = n;
    if (begin(row.count)) ++row.count;
  }
  run();
}

template <bool kTargets>
std::conditional_t<kTargets, TargetViews, NoTargets> target_views(const DrawRecord& d, const Framebuffer& fb) {
  std::conditional_t<kTargets, TargetViews, NoTargets> targets;
  if constexpr (kTargets) {
    for (int i = 0; i < fb.color_targets; ++i) {
      const DrawRecord& record = (*d.target_draws)[size_t(i)];
      if (!fb.target_color(i).base || !record.color_write_any) continue;
      targets.view[size_t(targets.count)] = fb.target(i);
      targets.record[size_t(targets.count)] = &record;
      targets.output[size_t(targets.count++)] = d.state.shader->program->broadcasts_color() ? 0 : i;
    }
  }
  return targets;
}

template <bool kTargets>
uint32_t shade_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                     const uint8_t* masks) {
  if (!d.state.shader || !d.state.shader->program) return 0;
  const ShaderDraw& sd = *d.state.shader;
  const F4 oy = quad_row_oy(p, y), ox0 = quad_row_ox0(p, x);
  const float* uniform_values = sd.fragment_uniform_values();
  const auto targets = target_views<kTargets>(d, fb);
  const UnitTextureAccess textures(d.state.texture_units, &d.shader_samplers);
  uint32_t passed = 0;
  RowBlocks row;
  const bool early = early_tests(d, *sd.program);
  auto begin = [&](int k) {
    if (early) early_tests_of_block(d, p, fb, y, row, k, passed);
    return begin_block(d, p, fb, y, uniform_values, row, k);
  };
  auto run = [&] {
    if (!row.count) return;
    sd.program->run_fragment_blocks(sd.uniforms.data(), &textures, row.blocks, row.count);
    for (int k = 0; k < row.count; ++k)
      passed += finish_block<kTargets>(d, p, fb, y, targets, row, k, row.blocks[k].live, early);
    row.count = 0;
  };
  auto keep = [&](int q, Quad& quad, int) {
    quad.mask = masks[q];
    if (d.key.extras) quad.mask &= stipple_mask(d, p, x + 2 * q, y);
    return quad.mask != 0;
  };
  group_quads(row, x, ox0, oy, count, keep, begin, run);
  return passed;
}

// A multisampled draw (sample_targets.h): each pixel any sample covers shaded once, then the
// operations after shading for each sample with its coverage, record, depth and plane.
template <bool kTargets>
uint32_t shade_sample_quads(const DrawRecord& d, const PrimSetup& p, const SampleTargets& t, int x, int y, int count,
                            const uint16_t* masks) {
  if (!d.state.shader || !d.state.shader->program) return 0;
  const ShaderDraw& sd = *d.state.shader;
  const F4 oy = quad_row_oy(p, y), ox0 = quad_row_ox0(p, x);
  const float* uniform_values = sd.fragment_uniform_values();
  int first = 0;  // a sample the draw writes: its plane has the framebuffer's draw buffers
  while (first < kMaxSamples - 1 && !t.draw[first]) ++first;
  std::array<std::conditional_t<kTargets, TargetViews, NoTargets>, kMaxSamples> targets;
  for (int s = 0; s < kMaxSamples; ++s)
    if (t.draw[s]) targets[size_t(s)] = target_views<kTargets>(*t.draw[s], t.plane[s]);
  const UnitTextureAccess textures(d.state.texture_units, &d.shader_samplers);
  // Alpha to coverage makes every sample's record alpha-test (multisample.cpp).
  const bool early = early_tests(d, *sd.program) && !d.sample_draws;
  uint32_t passed = 0;
  RowBlocks row;
  uint16_t sample_masks[RowBlocks::kMax][4];  // per quad of each block (sample_targets.h)
  auto begin = [&](int k) {
    for (int q = 0; q < row.quad_count[k]; ++q) {
      uint16_t& m = sample_masks[k][q];
      if (early) {  // every sample's stencil and depth at once
        const Quad& quad = row.quads[k][q];
        m = d.sample_tests(d, p, t, quad.x, y, quad.ox, quad.oy, m, nullptr);
        if (d.key.count_samples) passed += static_cast<uint32_t>(__builtin_popcount(m));
      }
      row.quads[k][q].mask = any_sample_mask(m);
    }
    return begin_block(d, p, t.plane[first], y, uniform_values, row, k);
  };
  // After shading, without early tests: each sample's alpha test (its own threshold under alpha
  // to coverage), then every sample's stencil and depth at once; what passes is left to write.
  const bool late = !early && (d.key.depth || d.key.stencil);
  auto late_tests = [&](int k) {
    const shader::FragmentBlock& block = row.blocks[k];
    for (int q = 0; q < row.quad_count[k]; ++q) {
      const Quad& quad = row.quads[k][q];
      const unsigned shaded = (block.live >> (4 * q)) & 0xfu;  // less the discarded fragments
      uint16_t m = static_cast<uint16_t>(sample_masks[k][q] & (shaded * 0x1111u));
      if (!m) continue;
      for (int s = 0; s < kMaxSamples; ++s)
        if (const unsigned mask = sample_quad_mask(m, s); mask && t.draw[s] && t.draw[s]->state.alpha_test) {
          const unsigned kept = alpha_test_quad(*t.draw[s], *t.prim[s], block, q, quad.x, y, mask);
          m = static_cast<uint16_t>(m & ~((mask & ~kept) << (4 * s)));
        }
      uint32_t z[4];
      if (sd.program->writes_depth()) shader_depths(d, block, q, z);
      m = d.sample_tests(d, p, t, quad.x, y, quad.ox, quad.oy, m, sd.program->writes_depth() ? z : nullptr);
      if (d.key.count_samples) passed += static_cast<uint32_t>(__builtin_popcount(m));
      sample_masks[k][q] = m;
    }
  };
  auto run = [&] {
    if (!row.count) return;
    sd.program->run_fragment_blocks(sd.uniforms.data(), &textures, row.blocks, row.count);
    for (int k = 0; k < row.count; ++k) {
      if (late) late_tests(k);
      for (int s = 0; s < kMaxSamples; ++s) {
        if (!t.draw[s]) continue;
        shader::LaneMask live = 0;
        for (int q = 0; q < row.quad_count[k]; ++q)
          live |= static_cast<shader::LaneMask>(sample_quad_mask(sample_masks[k][q], s) << (4 * q));
        live &= row.blocks[k].live;  // less the discarded fragments
        // The tests are done (early or late): finish_block writes (its alpha test passes again).
        if (live)
          passed += finish_block<kTargets>(*t.draw[s], *t.prim[s], t.plane[s], y, targets[size_t(s)], row, k, live,
                                           early || late);
      }
    }
    row.count = 0;
  };
  auto keep = [&](int q, Quad&, int n) {
    uint16_t& m = sample_masks[row.count][n];
    m = masks[q];
    if (d.key.extras) m &= static_cast<uint16_t>(stipple_mask(d, p, x + 2 * q, y) * 0x1111u);
    return any_sample_mask(m) != 0;
  };
  group_quads(row, x, ox0, oy, count, keep, begin, run);
  return passed;
}

}  // namespace

uint32_t shade_program_sample_quads(const DrawRecord& d, const PrimSetup& p, const SampleTargets& t, int x, int y,
                                    int count, const uint16_t* masks) {
  return shade_sample_quads<false>(d, p, t, x, y, count, masks);
}

uint32_t shade_program_target_sample_quads(const DrawRecord& d, const PrimSetup& p, const SampleTargets& t, int x,
                                           int y, int count, const uint16_t* masks) {
  return shade_sample_quads<true>(d, p, t, x, y, count, masks);
}

uint32_t shade_program_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                             const uint8_t* masks) {
  return shade_quads<false>(d, p, fb, x, y, count, masks);
}

uint32_t shade_program_target_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y,
                                    int count, const uint8_t* masks) {
  return shade_quads<true>(d, p, fb, x, y, count, masks);
}

}  // namespace pineda::raster
