#include "raster/shader_quads.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <memory>
#include <optional>
#include <type_traits>
#include <utility>

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
  else if (d.key.blend8 == Blend8::Over) write_quad<true, true>(d, fb, x, y, mask, col);
  else write_quad<true, false>(d, fb, x, y, mask, col);
}

// A quad to shade: its place, its pixels, and the primitive it belongs to (a block may hold
// quads of several primitives of one draw, from several rows).
// Left uninitialized: every field is set before a block reads it (group_quads, QuadBlocks::add_row).
struct Quad {
  int x, y;
  unsigned mask;
  const PrimSetup* prim;
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

// Whether a draw into `fb` (through `targets`, with several draw buffers) writes any colour.
template <bool kTargets>
bool writes_color(const DrawRecord& d, const Framebuffer& fb,
                  const std::conditional_t<kTargets, TargetViews, NoTargets>& targets) {
  if constexpr (kTargets) return targets.count > 0;
  else return fb.color.base && d.color_write_any;
}

// Up to four blocks shaded together (shader::Program::run_fragment_blocks): each block's
// quads, its fragment inputs, and what it needs after the run.
// Made for each row of quads shade_quads is given, it initializes only `count`: the rest of
// block k is set when the block is filled (group_quads, QuadBlocks::close_block, begin_block).
// Zeroing the blocks' fields and quads stored to 24 lines a row (glsl_sprites: 4% of a frame).
struct RowBlocks {
  static constexpr int kMax = shader::kMaxBlocksPerRun;
  RowBlocks() {}  // (not = default: that would construct `blocks`)
  int count = 0;
  Quad quads[kMax][4];
  int quad_count[kMax];
  // Block k's quads all of prim[k] (null: of several), and in one row left to right (one_row[k]).
  const PrimSetup* prim[kMax];
  bool one_row[kMax];
  union {  // not constructed: begin_block sets every field a run reads
    shader::FragmentBlock blocks[kMax];
  };
  alignas(64) float varyings[kMax][shader::kMaxVaryingFloats][kLanes];
};

bool early_tests(const DrawRecord& d) {
  return (d.key.depth || d.key.stencil) && !d.shader_facts.writes_depth && !d.shader_facts.uses_discard &&
         !d.state.alpha_test;
}

// Whether the program must run: after the early tests (which count the samples that pass), a
// draw that writes no colour leaves nothing for it to decide, so a depth-only pass (shadow maps,
// depth pre-passes) runs no shader.
bool runs_shader(bool early, bool write_color) { return !early || write_color; }

// Depth and stencil of quad q before shading (early_tests): its pixels that pass. Adds them to
// `passed` when the draw counts samples.
unsigned early_depth_stencil(const DrawRecord& d, const Framebuffer& fb, const Quad& q, unsigned mask,
                             uint32_t& passed) {
  const PrimSetup& p = *q.prim;
  if (!d.key.stencil) {  // the fixed-function routines' depth test: the same depths and results
    mask = depth_only(d, p, fb, q.x, q.y, mask, q.ox, q.oy);
  } else {
    uint32_t plane_z[4];
    plane_depths(d, p, q.ox, q.oy, plane_z);
    mask = depth_stencil_lanes(d, p, fb, q.x, q.y, mask, plane_z);
  }
  if (d.key.count_samples) passed += static_cast<uint32_t>(__builtin_popcount(mask));
  return mask;
}

// Fills in block k's prim and one_row from its quads.
void describe_block(RowBlocks& row, int k) {
  const Quad* quads = row.quads[k];
  const int n = row.quad_count[k];
  bool one_prim = true, one_row = true;
  for (int j = 1; j < n; ++j) {
    one_prim &= quads[j].prim == quads[0].prim;
    one_row &= quads[j].y == quads[0].y && quads[j].x > quads[j - 1].x;
  }
  row.prim[k] = one_prim ? quads[0].prim : nullptr;
  row.one_row[k] = one_row;
}

// Whether block k's quads are side by side, left to right, in one row.
bool adjacent_quads(const RowBlocks& row, int k) {
  if (!row.one_row[k]) return false;
  const Quad* quads = row.quads[k];
  for (int j = 1; j < row.quad_count[k]; ++j)
    if (quads[j].x != quads[0].x + 2 * j) return false;
  return true;
}

// Whether the first n quads lie inside the framebuffer, no two at one place (so that testing
// them at once gives what testing them in order would).
bool apart_inside(const Framebuffer& fb, const Quad* quads, int n) {
  for (int i = 0; i < n; ++i) {
    const Quad& q = quads[i];
    if (q.x < 0 || q.y < 0 || q.x + 2 > fb.width || q.y + 2 > fb.height) return false;
    for (int j = 0; j < i; ++j)
      if (quads[j].x == q.x && quads[j].y == q.y) return false;
  }
  return true;
}

// The lanes' offsets of a block of the first n quads (lanes of missing quads repeat quad 0's) for
// a block test, and its quads' pixels as its bits (bit 4j + i: quad j's pixel i).
unsigned block_offsets(const Quad* quads, int n, float* ox, float* oy) {
  unsigned quad_bits = 0;
  for (int j = 0; j < 4; ++j) {
    const Quad& q = quads[j < n ? j : 0];
    store4(&ox[4 * j], q.ox);
    store4(&oy[4 * j], q.oy);
    if (j < n) quad_bits |= q.mask << (4 * j);
  }
  return quad_bits;
}

// The first n quads keep their pixels of quad_bits (bit 4j + i: quad j's pixel i), which a test
// of the block passed; adds them to `passed` when the draw counts samples.
void keep_passing(const DrawRecord& d, Quad* quads, int n, unsigned quad_bits, uint32_t& passed) {
  for (int j = 0; j < n; ++j) quads[j].mask = (quad_bits >> (4 * j)) & 0xFu;
  if (d.key.count_samples) passed += static_cast<uint32_t>(__builtin_popcount(quad_bits));
}

// The early tests of block k of `row` (early_tests), in the quads' order, without stencil at
// once (block_depth.h): four adjacent quads of one primitive inside the buffer and one tile, or
// two to four quads inside the buffer and apart; others quad by quad. (A block of fewer adjacent
// quads tested as four, the missing ones' lanes testing nothing, measured no faster, twice.)
void early_tests_of_block(const DrawRecord& d, const Framebuffer& fb, RowBlocks& row, int k, uint32_t& passed) {
  Quad* quads = row.quads[k];
  const int n = row.quad_count[k];
  const int x = quads[0].x, y = quads[0].y;
  const PrimSetup& p = *quads[0].prim;
  const bool adjacent = n == 4 && row.prim[k] && adjacent_quads(row, k);
  if (!d.key.stencil && adjacent && x >= 0 && x + 8 <= fb.width && y >= 0 && y + 2 <= fb.height &&
      (x & (kTileSize - 1)) + 8 <= kTileSize) {
    static const BlockDepthTest test = select_block_depth_test(simd_path_from_environment());
    alignas(64) float ox[kLanes], oy[kLanes];
    const unsigned quad_bits = block_offsets(quads, 4, ox, oy);
    return keep_passing(d, quads, 4, test(d, p, fb, x, y, ox, oy, quad_bits), passed);
  }
  // Small triangles' quads packed into one block (QuadBlocks), a row's last two or three quads.
  if (!d.key.stencil && n > 1 && apart_inside(fb, quads, n)) {
    static const QuadsDepthTest test = select_quads_depth_test(simd_path_from_environment());
    BlockQuads places;
    for (int j = 0; j < 4; ++j) {
      const Quad& q = quads[j < n ? j : 0];
      places.x[j] = q.x;
      places.y[j] = q.y;
      places.prim[j] = q.prim;
    }
    alignas(64) float ox[kLanes], oy[kLanes];
    const unsigned quad_bits = block_offsets(quads, n, ox, oy);
    return keep_passing(d, quads, n, test(d, places, fb, ox, oy, quad_bits), passed);
  }
  for (int q = 0; q < n; ++q) quads[q].mask = early_depth_stencil(d, fb, quads[q], quads[q].mask, passed);
}

// The varyings and 1/w of block k's lanes (unused quads repeat quad 0: derivatives stay finite),
// each quad's from its own primitive's planes.
[[gnu::always_inline]] inline void interpolate_block(int nv, const RowBlocks& row, int k, float (*varyings)[kLanes],
                                                   float* w) {
  static const VaryingInterpolator interpolate = select_varying_interpolator(simd_path_from_environment());
  const Quad* quads = row.quads[k];
  const int n = row.quad_count[k];
  alignas(64) float ox[kLanes], oy[kLanes];
  for (int j = 0; j < 4; ++j) {
    const Quad& q = quads[j < n ? j : 0];
    store4(&ox[4 * j], q.ox);
    store4(&oy[4 * j], q.oy);
  }
  if (const PrimSetup* p = row.prim[k]) {
    interpolate(p->varying_planes, nv, p->inv_w, p->perspective, ox, oy, varyings, w);
    return;
  }
  static const QuadVaryingInterpolator interpolate_quads = select_quad_varying_interpolator(simd_path_from_environment());
  QuadPlanes planes;
  for (int j = 0; j < 4; ++j) {
    const PrimSetup& p = *quads[j < n ? j : 0].prim;
    planes.planes[j] = p.varying_planes;
    planes.inv_w[j] = &p.inv_w;
    planes.perspective[j] = p.perspective;
  }
  interpolate_quads(planes, nv, ox, oy, varyings, w);
}

// gl_FragCoord (window z only when `components` has it) and, when `point_coord`, gl_PointCoord
// of block k's lanes, a quad at a time; w: the lanes' 1/w.
void fill_frag_coords(const DrawRecord& d, int nv, const RowBlocks& row, int k, const float* w, unsigned components,
                      bool point_coord, shader::FragmentBlock& block) {
  using I4 = int32_t __attribute__((vector_size(16)));
  const Quad* quads = row.quads[k];
  const int n = row.quad_count[k];
  for (int j = 0; j < 4; ++j) {
    const Quad& q = quads[j < n ? j : 0];
    const PrimSetup& p = *q.prim;
    const F4 fx = __builtin_convertvector((I4{q.x, q.x + 1, q.x, q.x + 1}), F4) + splat(0.5f);
    const F4 fy = __builtin_convertvector((I4{q.y, q.y, q.y + 1, q.y + 1}), F4) + splat(0.5f);
    store4(&block.frag_coord[0][4 * j], fx);
    store4(&block.frag_coord[1][4 * j], fy);
    if (components & 4u)
      for (int i = 0; i < 4; ++i) {
        double z = p.z0 + p.dzdx * static_cast<double>(q.ox[i]) + p.dzdy * static_cast<double>(q.oy[i]);
        z = z > 0.0 ? (z < d.depth_max ? z : d.depth_max) : 0.0;
        block.frag_coord[2][4 * j + i] = static_cast<float>(z / d.depth_max);
      }
    if (!point_coord) continue;
    // Zeros where there is no sprite.
    const float* point = p.kind == CoverageKind::Point && p.varying_planes ? &p.varying_planes[nv].a0 : nullptr;
    const bool sprite = point && point[2] > 0.f;
    store4(&block.point_coord[0][4 * j], sprite ? splat(0.5f) + (fx - splat(point[0])) / splat(point[2]) : F4{});
    store4(&block.point_coord[1][4 * j], sprite ? splat(0.5f) - (fy - splat(point[1])) / splat(point[2]) : F4{});
  }
  std::memcpy(block.frag_coord[3], w, sizeof block.frag_coord[3]);
}

// Fills block k of `row` for its quads (after any early tests); returns false when no pixel is
// left to shade.
bool begin_block(const DrawRecord& d, const Framebuffer& fb, const float* uniform_values, RowBlocks& row, int k) {
  const ShaderDraw& sd = *d.state.shader;
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
    const bool one_row = row.one_row[k];
    for (int j = 0; j < (one_row ? 1 : n); ++j) {
      const Quad& q = quads[j];
      const int x1 = one_row ? std::min(q.x + 7, fb.width - 1) : q.x + 1;  // maybe on the next line
      __builtin_prefetch(color_address(fb, q.x, q.y), 1);
      __builtin_prefetch(color_address(fb, x1, q.y), 1);
      if (one_row ? (block.live & 0xCCCCu) : (q.mask & 0xCu)) {  // else the row above may lie past the buffer
        __builtin_prefetch(color_address(fb, q.x, q.y + 1), 1);
        __builtin_prefetch(color_address(fb, x1, q.y + 1), 1);
      }
    }
  }

  const DrawRecord::ShaderFacts& facts = d.shader_facts;
  const int nv = facts.varying_floats;
  float (*varyings)[kLanes] = row.varyings[k];
  alignas(64) float w[kLanes];
  interpolate_block(nv, row, k, varyings, w);
  if (row.prim[k]) {
    block.front_facing = row.prim[k]->back_facing ? 0 : 0xffff;
  } else {
    block.front_facing = 0;
    for (int j = 0; j < 4; ++j)
      if (!quads[j < n ? j : 0].prim->back_facing) block.front_facing |= static_cast<shader::LaneMask>(0xfu << (4 * j));
  }
  // Only the components the program reads (glmark2's conditionals, function and loop scenes read
  // gl_FragCoord.xy: the depth's per-lane doubles took half of begin_block there).
  if (facts.frag_coord_components || facts.reads_point_coord)
    fill_frag_coords(d, nv, row, k, w, facts.frag_coord_components, facts.reads_point_coord, block);
  // A colour buffer the program does not write reads as zeros.
  if (sd.color_output >= facts.draw_buffers_written)
    std::fill(&block.color[sd.color_output][0][0], &block.color[sd.color_output][0][0] + 4 * kLanes, 0.f);
  if (sd.color_output != 0 && s.alpha_test)  // colour 0's alpha is tested even if never written
    std::fill(&block.color[0][3][0], &block.color[0][3][0] + kLanes, 0.f);
  if (!facts.broadcasts_color)  // else colour 0 serves every draw buffer
    for (int i = facts.draw_buffers_written; i < fb.color_targets; ++i)
      std::fill(&block.color[i][0][0], &block.color[i][0][0] + 4 * kLanes, 0.f);
  block.varyings = &varyings[0][0];
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
  if (d.key.extras) apply_coverage(p, x, y, mask, alpha);
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

// How block k's colours get written: all at once (block_write.h) when its live pixels all get
// written, each wholly and in the same way, nothing but the colour and coverage left to decide,
// and no pixel live in two of its quads (the later one's blend reads the earlier one's write);
// else quad by quad.
enum class BlockWrite { PerQuad, Adjacent, Apart };

BlockWrite block_write(const DrawRecord& d, const Framebuffer& fb, const RowBlocks& row, int k, shader::LaneMask live,
                       bool no_late_tests, bool write_color) {
  const DrawState& s = d.state;
  if (!write_color || !no_late_tests || d.key.extras || s.alpha_test || d.alpha_to_one || !d.color_write_all ||
      fb.color.reduction.active || (d.key.blend && d.key.blend8 == Blend8::Other))
    return BlockWrite::PerQuad;
  if (adjacent_quads(row, k)) return BlockWrite::Adjacent;
  if (row.one_row[k]) return BlockWrite::Apart;
  const Quad* quads = row.quads[k];
  const int n = row.quad_count[k];
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (quads[i].x == quads[j].x && quads[i].y == quads[j].y && ((live >> (4 * i)) & (live >> (4 * j)) & 0xfu))
        return BlockWrite::PerQuad;
  return BlockWrite::Apart;
}

// After the run: alpha test, late depth and stencil, colour writes of the `live` lanes of block
// k (the block's own live lanes, or a sample's: shade_sample_quads), in the quads' order;
// returns the samples that passed a late depth test. Each quad's primitive gives its depth, or
// `sample_prim` (a sample's) when set; the colours are the block's.
template <bool kTargets>
uint32_t finish_block(const DrawRecord& d, const PrimSetup* sample_prim, const Framebuffer& fb,
                      const std::conditional_t<kTargets, TargetViews, NoTargets>& targets, const RowBlocks& row, int k,
                      shader::LaneMask live_lanes, bool early) {
  const ShaderDraw& sd = *d.state.shader;
  const DrawState& s = d.state;
  const shader::FragmentBlock& block = row.blocks[k];
  const bool tests = d.key.depth || d.key.stencil;
  const bool write_color = writes_color<kTargets>(d, fb, targets);
  uint32_t passed = 0;
  if constexpr (!kTargets) {
    const BlockWrite how = block_write(d, fb, row, k, live_lanes, early || !tests, write_color);
    if (how != BlockWrite::PerQuad) {
      const int n = row.quad_count[k];
      const auto live = static_cast<uint16_t>(live_lanes & ((1u << (4 * n)) - 1u));
      const uint32_t* shift = fb.color.format == ColorFormat::BGRA8 ? kBgraShift.at : kRgbaShift.at;
      const Blend8 blend = d.key.blend ? d.key.blend8 : Blend8::Other;
      // The writers touch the live pixels alone; a row without any may lie past the buffer, and
      // is not addressed.
      if (how == BlockWrite::Adjacent) {
        static const BlockWriter write = select_block_writer(simd_path_from_environment());
        const Quad& q = row.quads[k][0];
        uint8_t* const row0 = color_address(fb, q.x, q.y);
        uint8_t* const row1 = (live & 0xCCCCu) ? color_address(fb, q.x, q.y + 1) : row0;
        write(block.color[sd.color_output], shift, blend, row0, row1, live);
      } else {
        static const QuadsWriter write = select_quads_writer(simd_path_from_environment());
        // Rows without a pixel to write point at spare bytes: a masked move at an address it
        // may not touch costs a microcode assist (glsl_sprites ran 2.5 times as long).
        alignas(8) uint8_t spare[8];
        uint8_t* rows[8];
        std::fill_n(rows, 8, &spare[0]);
        for (int j = 0; j < n; ++j) {
          const Quad& q = row.quads[k][j];
          if (live & (0x3u << (4 * j))) rows[2 * j] = color_address(fb, q.x, q.y);
          if (live & (0xCu << (4 * j))) rows[2 * j + 1] = color_address(fb, q.x, q.y + 1);
        }
        write(block.color[sd.color_output], shift, blend, rows, live);
      }
      return d.key.count_samples && !early ? static_cast<uint32_t>(__builtin_popcount(live)) : 0;
    }
  }
  for (int j = 0; j < row.quad_count[k]; ++j) {
    unsigned mask = (live_lanes >> (4 * j)) & 0xfu;
    if (!mask) continue;
    const Quad& q = row.quads[k][j];
    const PrimSetup& p = sample_prim ? *sample_prim : *q.prim;
    const int y = q.y;
    QuadColor col;
    for (int c = 0; c < 4; ++c) col.c[c] = load4(&block.color[sd.color_output][c][4 * j]);
    if (d.key.extras) apply_coverage(p, q.x, y, mask, col.c[3]);
    if (s.alpha_test) mask = alpha_test_quad(d, p, block, j, q.x, y, mask);
    if (d.alpha_to_one) col.c[3] = splat(1.f);  // after alpha to coverage (the alpha test above)
    if (!early && tests) {
      uint32_t z[4];
      if (d.shader_facts.writes_depth) shader_depths(d, block, j, z);
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
        if (d.key.extras) apply_coverage(p, q.x, y, mask, out.c[3]);
        if (d.alpha_to_one) out.c[3] = splat(1.f);
        write_colors(*targets.record[size_t(t)], targets.view[size_t(t)], q.x, y, mask, out);
      }
    }
  }
  return passed;
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

// The quads of one draw's rows from several primitives in order (ShaderQuadBatch), packed into
// full blocks whatever their rows and primitives (small triangles cover a quad or two each),
// shaded four blocks at a time, then tested and written in the order they came: a later quad at
// the same pixel is tested and written after the earlier one, as unpacked.
class QuadBlocks {
 public:
  QuadBlocks(const DrawRecord& d, const Framebuffer& fb, RowBlocks& row)
      : d_(d), fb_(fb), sd_(*d.state.shader), row_(row), uniform_values_(sd_.fragment_uniform_values()),
        textures_(d.state.texture_units, &d.shader_samplers),
        early_(early_tests(d)),
        shade_(runs_shader(early_, writes_color<false>(d, fb, NoTargets{}))) {
    row_.count = 0;
  }

  const DrawRecord& draw() const { return d_; }

  void add_row(const PrimSetup& p, int x, int y, int count, const uint8_t* masks) {
    const F4 oy = quad_row_oy(p, y), ox0 = quad_row_ox0(p, x);
    for (int q = 0; q < count; ++q) {
      Quad& quad = row_.quads[row_.count][filling_];
      quad.mask = masks[q];
      if (d_.key.extras) quad.mask &= stipple_mask(d_, p, x + 2 * q, y);
      if (!quad.mask) continue;
      quad.x = x + 2 * q;
      quad.y = y;
      quad.prim = &p;
      quad.ox = ox0 + splat(static_cast<float>(2 * q));
      quad.oy = oy;
      if (++filling_ == 4) close_block();
    }
  }

  // Shades and writes everything added; returns the samples that passed since the last flush.
  uint32_t flush() {
    if (filling_) close_block();
    run();
    return std::exchange(passed_, 0);
  }

 private:
  void close_block() {
    const int k = row_.count;
    row_.quad_count[k] = filling_;
    filling_ = 0;
    describe_block(row_, k);
    if (early_) early_tests_of_block(d_, fb_, row_, k, passed_);
    if (shade_ && begin_block(d_, fb_, uniform_values_, row_, k)) ++row_.count;
    if (row_.count == RowBlocks::kMax) run();
  }

  void run() {
    if (!row_.count) return;
    sd_.program->run_fragment_blocks(sd_.uniforms.data(), &textures_, row_.blocks, row_.count);
    for (int k = 0; k < row_.count; ++k)
      passed_ += finish_block<false>(d_, nullptr, fb_, NoTargets{}, row_, k, row_.blocks[k].live, early_);
    row_.count = 0;
  }

  const DrawRecord& d_;
  const Framebuffer& fb_;
  const ShaderDraw& sd_;
  RowBlocks& row_;
  const float* uniform_values_;
  const UnitTextureAccess textures_;
  const bool early_;
  const bool shade_;
  int filling_ = 0;  // quads in block row_.count so far
  uint32_t passed_ = 0;
};

// The quads of a row that `keep(q, quad, n)` keeps (quad n of the block being filled; false:
// no pixel of quad q to shade) in blocks of up to four: begin(k) fills block k (false: nothing
// left in it to shade), run() shades the blocks so far and empties the row.
template <class Keep, class Begin, class Run>
[[gnu::always_inline]] inline void group_quads(RowBlocks& row, const PrimSetup& p, int x, int y, int count,
                                               const Keep& keep, const Begin& begin, const Run& run) {
  const F4 oy = quad_row_oy(p, y), ox0 = quad_row_ox0(p, x);
  int n = 0;
  for (int q = 0; q < count; ++q) {
    Quad& quad = row.quads[row.count][n];
    if (!keep(q, quad, n)) continue;
    quad.x = x + 2 * q;
    quad.y = y;
    quad.prim = &p;
    quad.ox = ox0 + splat(static_cast<float>(2 * q));
    quad.oy = oy;
    if (++n == 4 || q == count - 1) {
      row.quad_count[row.count] = n;
      row.prim[row.count] = &p;
      row.one_row[row.count] = true;
      if (begin(row.count)) ++row.count;
      n = 0;
      if (row.count == RowBlocks::kMax) run();
    }
  }
  if (n) {
    row.quad_count[row.count] = n;
    row.prim[row.count] = &p;
    row.one_row[row.count] = true;
    if (begin(row.count)) ++row.count;
  }
  run();
}

template <bool kTargets>
uint32_t shade_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                     const uint8_t* masks) {
  if (!d.state.shader || !d.state.shader->program) return 0;
  const ShaderDraw& sd = *d.state.shader;
  const float* uniform_values = sd.fragment_uniform_values();
  const auto targets = target_views<kTargets>(d, fb);
  const UnitTextureAccess textures(d.state.texture_units, &d.shader_samplers);
  uint32_t passed = 0;
  RowBlocks row;
  const bool early = early_tests(d);
  const bool write_color = writes_color<kTargets>(d, fb, targets);
  const bool shade = runs_shader(early, write_color);
  auto begin = [&](int k) {
    if (early) early_tests_of_block(d, fb, row, k, passed);
    return shade && begin_block(d, fb, uniform_values, row, k);
  };
  auto run = [&] {
    if (!row.count) return;
    sd.program->run_fragment_blocks(sd.uniforms.data(), &textures, row.blocks, row.count);
    for (int k = 0; k < row.count; ++k)
      passed += finish_block<kTargets>(d, nullptr, fb, targets, row, k, row.blocks[k].live, early);
    row.count = 0;
  };
  auto keep = [&](int q, Quad& quad, int) {
    quad.mask = masks[q];
    if (d.key.extras) quad.mask &= stipple_mask(d, p, x + 2 * q, y);
    return quad.mask != 0;
  };
  group_quads(row, p, x, y, count, keep, begin, run);
  return passed;
}

// A multisampled draw (sample_targets.h): each pixel any sample covers shaded once, then the
// operations after shading for each sample with its coverage, record, depth and plane.
template <bool kTargets>
uint32_t shade_sample_quads(const DrawRecord& d, const PrimSetup& p, const SampleTargets& t, int x, int y, int count,
                            const uint16_t* masks) {
  if (!d.state.shader || !d.state.shader->program) return 0;
  const ShaderDraw& sd = *d.state.shader;
  const float* uniform_values = sd.fragment_uniform_values();
  int first = 0;  // a sample the draw writes: its plane has the framebuffer's draw buffers
  while (first < kMaxSamples - 1 && !t.draw[first]) ++first;
  std::array<std::conditional_t<kTargets, TargetViews, NoTargets>, kMaxSamples> targets;
  for (int s = 0; s < kMaxSamples; ++s)
    if (t.draw[s]) targets[size_t(s)] = target_views<kTargets>(*t.draw[s], t.plane[s]);
  const UnitTextureAccess textures(d.state.texture_units, &d.shader_samplers);
  // Alpha to coverage makes every sample's record alpha-test (multisample.cpp).
  const bool early = early_tests(d) && !d.sample_draws;
  bool write_color = false;  // to any sample
  for (int s = 0; s < kMaxSamples; ++s)
    if (t.draw[s]) write_color |= writes_color<kTargets>(*t.draw[s], t.plane[s], targets[size_t(s)]);
  const bool shade = runs_shader(early, write_color);
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
    return shade && begin_block(d, t.plane[first], uniform_values, row, k);
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
          passed += finish_block<kTargets>(*t.draw[s], t.prim[s], t.plane[s], targets[size_t(s)], row, k, live,
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
  group_quads(row, p, x, y, count, keep, begin, run);
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

struct ShaderQuadBatch::Blocks {
  RowBlocks row;
  std::optional<QuadBlocks> blocks;
};

ShaderQuadBatch::ShaderQuadBatch() = default;
ShaderQuadBatch::~ShaderQuadBatch() = default;

bool ShaderQuadBatch::takes(const DrawRecord& d) { return d.routine == shade_program_quads; }

const DrawRecord* ShaderQuadBatch::draw() const {
  return blocks_ && blocks_->blocks ? &blocks_->blocks->draw() : nullptr;
}

void ShaderQuadBatch::add_row(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                              const uint8_t* masks) {
  if (!d.state.shader || !d.state.shader->program) return;
  if (const DrawRecord* waiting = draw(); waiting && waiting != &d) {  // (Scene::run_tile flushes first)
    if (const uint32_t passed = flush()) waiting->state.sample_counter->passed.fetch_add(passed, std::memory_order_relaxed);
  }
  if (!blocks_) blocks_.reset(new Blocks);  // not make_unique: its value-initialization zeroed 50 KB a tile
  if (!blocks_->blocks) blocks_->blocks.emplace(d, fb, blocks_->row);
  blocks_->blocks->add_row(p, x, y, count, masks);
}

uint32_t ShaderQuadBatch::flush() {
  if (!blocks_ || !blocks_->blocks) return 0;
  const uint32_t passed = blocks_->blocks->flush();
  blocks_->blocks.reset();
  return passed;
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
