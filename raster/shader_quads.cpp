#include "raster/shader_quads.h"

#include <algorithm>
#include <array>
#include <type_traits>

#include "raster/fragment_extras.h"
#include "raster/fragment_ops.h"
#include "raster/quad_ops.h"
#include "raster/shader_draw.h"
#include "raster/shader_textures.h"

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

// Shades up to four quads of row y as one block; returns the samples that passed depth.
// kTargets: the framebuffer has several draw buffers, gl_FragData[i] (or gl_FragColor) goes to
// draw buffer i, all from one run of the shader.
template <bool kTargets>
uint32_t shade_block(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int y, Quad* quads, int n,
                     const float* uniform_values) {
  const ShaderDraw& sd = *d.state.shader;
  const shader::Program& program = *sd.program;
  const DrawState& s = d.state;
  const bool count = d.key.count_samples;
  const bool tests = d.key.depth || d.key.stencil;
  const bool early = tests && !program.writes_depth() && !program.uses_discard() && !s.alpha_test;
  uint32_t passed = 0;
  uint32_t plane_z[4][4];
  if (early) {  // depth and stencil first: only surviving fragments are shaded
    for (int k = 0; k < n; ++k) {
      plane_depths(d, p, quads[k].ox, quads[k].oy, plane_z[k]);
      quads[k].mask = depth_stencil_lanes(d, p, fb, quads[k].x, y, quads[k].mask, plane_z[k]);
      if (count) passed += static_cast<uint32_t>(__builtin_popcount(quads[k].mask));
    }
  }
  shader::FragmentBlock block;  // filled below as far as the program reads it
  for (int k = 0; k < n; ++k) block.live |= static_cast<shader::LaneMask>(quads[k].mask << (4 * k));
  if (!block.live) return passed;

  const int nv = program.varying_floats();
  alignas(64) float varyings[shader::kMaxVaryingFloats][kLanes];
  const float* point = p.kind == CoverageKind::Point && p.varying_planes ? &p.varying_planes[nv].a0 : nullptr;
  const bool frag_coord = program.reads_frag_coord();
  for (int k = 0; k < 4; ++k) {
    const Quad& q = quads[k < n ? k : 0];  // unused lanes repeat quad 0: derivatives stay finite
    const F4 w = eval_plane(p.inv_w, q.ox, q.oy);
    const F4 inv = 1.f / w;
    for (int v = 0; v < nv; ++v) {
      F4 value = eval_plane(p.varying_planes[v], q.ox, q.oy);
      if (p.perspective) value *= inv;
      store4(&varyings[v][4 * k], value);
    }
    if (!frag_coord && !point) continue;
    for (int i = 0; i < 4; ++i) {
      const int lane = 4 * k + i;
      const float fx = static_cast<float>(q.x + (i & 1)) + 0.5f, fy = static_cast<float>(y + (i >> 1)) + 0.5f;
      block.frag_coord[0][lane] = fx;
      block.frag_coord[1][lane] = fy;
      double z = p.z0 + p.dzdx * static_cast<double>(q.ox[i]) + p.dzdy * static_cast<double>(q.oy[i]);
      z = z > 0.0 ? (z < d.depth_max ? z : d.depth_max) : 0.0;
      block.frag_coord[2][lane] = static_cast<float>(z / d.depth_max);
      block.frag_coord[3][lane] = w[i];
      if (point && point[2] > 0.f) {
        block.point_coord[0][lane] = 0.5f + (fx - point[0]) / point[2];
        block.point_coord[1][lane] = 0.5f - (fy - point[1]) / point[2];
      }
    }
  }
  if (!point || !(point[2] > 0.f)) std::fill(&block.point_coord[0][0], &block.point_coord[0][0] + 2 * kLanes, 0.f);
  // A colour buffer the program does not write reads as zeros.
  if (sd.color_output >= program.draw_buffers_written())
    std::fill(&block.color[sd.color_output][0][0], &block.color[sd.color_output][0][0] + 4 * kLanes, 0.f);
  if (sd.color_output != 0 && s.alpha_test)  // colour 0's alpha is tested even if never written
    std::fill(&block.color[0][3][0], &block.color[0][3][0] + kLanes, 0.f);
  std::conditional_t<kTargets, TargetViews, NoTargets> targets;
  if constexpr (kTargets) {
    for (int i = program.draw_buffers_written(); i < fb.color_targets; ++i)
      std::fill(&block.color[i][0][0], &block.color[i][0][0] + 4 * kLanes, 0.f);
    for (int i = 0; i < fb.color_targets; ++i) {
      const DrawRecord& record = (*d.target_draws)[size_t(i)];
      if (!fb.target_color(i).base || !record.color_write_any) continue;
      targets.view[size_t(targets.count)] = fb.target(i);
      targets.record[size_t(targets.count)] = &record;
      targets.output[size_t(targets.count++)] = i;
    }
  }
  block.varyings = &varyings[0][0];
  block.front_facing = p.back_facing ? 0 : 0xffff;
  block.run = 0xffff;  // the unused quads repeat quad 0
  block.uniform_values = uniform_values;
  const UnitTextureAccess textures(s.texture_units);
  program.run_fragments(sd.uniforms.data(), &textures, block);

  bool write_color = fb.color.base && d.color_write_any;
  if constexpr (kTargets) write_color = targets.count > 0;
  for (int k = 0; k < n; ++k) {
    unsigned mask = (block.live >> (4 * k)) & 0xfu;
    if (!mask) continue;
    const Quad& q = quads[k];
    QuadColor col;
    for (int c = 0; c < 4; ++c) col.c[c] = load4(&block.color[sd.color_output][c][4 * k]);
    if (d.key.extras) apply_coverage(p, q.x, y, col.c[3]);
    if (s.alpha_test) {
      // The alpha of colour 0 decides for every draw buffer (as in Mesa; GL 3.0 4.1.4).
      F4 alpha = col.c[3];
      if (sd.color_output != 0) {
        alpha = load4(&block.color[0][3][4 * k]);
        if (d.key.extras) apply_coverage(p, q.x, y, alpha);
      }
      for (int i = 0; i < 4; ++i)
        if (!compare(s.alpha_func, clamp01(alpha[i]), d.alpha_ref)) mask &= ~(1u << i);
    }
    if (d.alpha_to_one) col.c[3] = splat(1.f);  // after alpha to coverage (the alpha test above)
    if (!early && tests) {
      uint32_t z[4];
      if (program.writes_depth()) {
        for (int i = 0; i < 4; ++i) {
          const float v = clamp01(block.depth[4 * k + i]);
          z[i] = static_cast<uint32_t>(static_cast<double>(v) * d.depth_max + 0.5);
        }
      } else {
        plane_depths(d, p, q.ox, q.oy, z);
      }
      mask = depth_stencil_lanes(d, p, fb, q.x, y, mask, z);
    }
    if (count && !early) passed += static_cast<uint32_t>(__builtin_popcount(mask));
    if (!mask || !write_color) continue;
    if constexpr (!kTargets) {
      write_colors(d, fb, q.x, y, mask, col);
    } else {
      for (int t = 0; t < targets.count; ++t) {
        QuadColor out;
        for (int c = 0; c < 4; ++c) out.c[c] = load4(&block.color[targets.output[size_t(t)]][c][4 * k]);
        if (d.key.extras) apply_coverage(p, q.x, y, out.c[3]);
        if (d.alpha_to_one) out.c[3] = splat(1.f);
        write_colors(*targets.record[size_t(t)], targets.view[size_t(t)], q.x, y, mask, out);
      }
    }
  }
  return passed;
}

template <bool kTargets>
uint32_t shade_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                     const uint8_t* masks) {
  if (!d.state.shader || !d.state.shader->program) return 0;
  const F4 oy = splat(static_cast<float>(y) + 0.5f - p.ref_y) + F4{0.f, 0.f, 1.f, 1.f};
  const F4 ox0 = splat(static_cast<float>(x) + 0.5f - p.ref_x) + F4{0.f, 1.f, 0.f, 1.f};
  const float* uniform_values = d.state.shader->fragment_uniform_values();
  uint32_t passed = 0;
  Quad quads[4];
  int n = 0;
  for (int q = 0; q < count; ++q) {
    unsigned mask = masks[q];
    if (d.key.extras) mask &= stipple_mask(d, p, x + 2 * q, y);
    if (!mask) continue;
    quads[n].x = x + 2 * q;
    quads[n].mask = mask;
    quads[n].ox = ox0 + splat(static_cast<float>(2 * q));
    quads[n].oy = oy;
    if (++n == 4) {
      passed += shade_block<kTargets>(d, p, fb, y, quads, n, uniform_values);
      n = 0;
    }
  }
  if (n) passed += shade_block<kTargets>(d, p, fb, y, quads, n, uniform_values);
  return passed;
}

}  // namespace

uint32_t shade_program_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y, int count,
                             const uint8_t* masks) {
  return shade_quads<false>(d, p, fb, x, y, count, masks);
}

uint32_t shade_program_target_quads(const DrawRecord& d, const PrimSetup& p, const Framebuffer& fb, int x, int y,
                                    int count, const uint8_t* masks) {
  return shade_quads<true>(d, p, fb, x, y, count, masks);
}

}  // namespace pineda::raster
