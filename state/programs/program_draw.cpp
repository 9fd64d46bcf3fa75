#include "state/programs/program_draw.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <new>
#include <string_view>

#include <xmmintrin.h>

#include "raster/draw_record.h"
#include "raster/float_modes.h"
#include "raster/renderer.h"
#include "raster/shader_draw.h"
#include "raster/shader_textures.h"
#include "state/context.h"
#include "state/programs/builtin_uniforms.h"
#include "state/programs/varyings_from_lanes.h"
#include "state/select_feedback.h"
#include "state/textures/texture_target.h"
#include "state/vertex_arrays/vertex_fetch.h"

namespace pineda {
namespace {

using shader::kLanes;

bool sampler_target(shader::BaseType b, TexTarget& out) {
  switch (b) {
    case shader::BaseType::Sampler1D: case shader::BaseType::Sampler1DShadow: out = TexTarget::T1D; return true;
    case shader::BaseType::Sampler2D: case shader::BaseType::Sampler2DShadow: out = TexTarget::T2D; return true;
    case shader::BaseType::Sampler3D: out = TexTarget::T3D; return true;
    case shader::BaseType::SamplerCube: out = TexTarget::Cube; return true;
    case shader::BaseType::Sampler2DRect: case shader::BaseType::Sampler2DRectShadow: out = TexTarget::Rect; return true;
    default: return false;
  }
}

// The texture units the program's samplers read, by their type's target (GL 2.0 2.15.4:
// sampler types choose the target, the enables do not matter).
void snapshot_sampler_textures(Context& ctx, const shader::Program& program, const std::vector<float>& values,
                               raster::DrawState& state) {
  // A unit without an image is off whatever else it holds (resetting every unit's fields was a
  // twentieth of a small program draw).
  for (raster::TextureUnit& unit : state.texture_units)
    if (unit.image) unit = raster::TextureUnit{};
  for (const shader::Uniform& u : program.uniforms()) {
    TexTarget target;
    if (u.builtin || !sampler_target(u.type.base, target)) continue;
    for (int e = 0; e < std::max(u.array_size, 1); ++e) {
      const size_t at = static_cast<size_t>(u.offset + e * u.stride);
      if (at >= values.size()) break;
      const int index = static_cast<int>(values[at]);
      if (index < 0 || index >= raster::kMaxTextureImageUnits) continue;
      raster::TextureUnit& out = state.texture_units[index];
      out = raster::TextureUnit{};
      TextureObject& tex = ctx.textures.get_or_create(bound_name(ctx.texture_units[index], target), binding_enum(target));
      const SamplerObject* sampler = ctx.texture_units[index].sampler.get();
      const TexParams* sampling = sampler ? &sampler->params : nullptr;
      out.image = tex.snapshot(sampling, attached_to_draw_framebuffer(ctx, tex));
      if (!out.image) continue;
      out.sampler = tex.sampler(sampling);
      out.sampler.lod_bias = std::clamp(out.sampler.lod_bias + ctx.texture_units[index].env.lod_bias,
                                        -kMaxTextureLodBias, kMaxTextureLodBias);
    }
  }
}

// Value of a built-in vertex input (desktop GLSL) for vertex v.
void builtin_input(const raster::VertexInput& v, shader::BuiltinAttribute kind, float out[4]) {
  out[0] = out[1] = out[2] = 0.f;
  out[3] = 1.f;
  using BA = shader::BuiltinAttribute;
  switch (kind) {
    case BA::None: return;
    case BA::Vertex: std::copy(v.position, v.position + 4, out); return;
    case BA::Normal: std::copy(v.normal, v.normal + 3, out); return;
    case BA::Color: std::copy(v.color, v.color + 4, out); return;
    case BA::SecondaryColor: std::copy(v.secondary_color, v.secondary_color + 3, out); return;
    case BA::FogCoord: out[0] = v.fog_coord; return;
    default: {
      const int unit = static_cast<int>(kind) - static_cast<int>(BA::MultiTexCoord0);
      if (unit >= 0 && unit < raster::kMaxTextureUnits) std::copy(v.texcoord[unit], v.texcoord[unit] + 4, out);
      return;
    }
  }
}

// Bit p: user clip plane p is enabled.
uint32_t enabled_clip_planes(const Context& ctx) {
  uint32_t planes = 0;
  for (int p = 0; p < raster::kMaxClipPlanes; ++p)
    if (ctx.extras.clip_plane_enabled[p]) planes |= 1u << p;
  return planes;
}

// Into `fetches` (emptied first).
void input_fetches(const Context& ctx, const shader::Program& program, AttribSource source, int slots,
                   std::vector<InputFetch>& fetches) {
  fetches.clear();
  for (const shader::Attribute& a : program.attributes()) {
    const int per_element = std::max<int>(a.type.columns, 1);
    const int slot_count = per_element * std::max(a.array_size, 1);
    for (int s = 0; s < slot_count; ++s) {
      InputFetch f;
      f.slot = a.input_slot + s;
      if (f.slot < 0 || f.slot >= slots) continue;
      f.builtin = a.builtin;
      f.location = a.location + s;
      if (f.builtin == shader::BuiltinAttribute::None) {
        if (f.location < 0 || f.location >= kMaxVertexAttribs) continue;
        f.from_view = direct_array_view(ctx, source, f.location, f.view);
      }
      fetches.push_back(f);
    }
  }
}

// A directly read array's elements[0..count) into an input slot's lanes: component c of vertex i
// at lanes[(i / kLanes) * batch_floats + c * kLanes + i % kLanes], missing components (0, 0, 0, 1)
// and an element past the buffer the attribute's current value, as DirectArrayView::read gives
// them. One routine per element size and type, so that the loop has no branch but the buffer's end.
template <int kSize, bool kUnorm8>
void gather_direct_array_of(const DirectArrayView& view, const uint32_t* elements, size_t count, float* lanes,
                            size_t batch_floats) {
  // Four vertices at a time (consecutive lanes of one batch, which holds a multiple of four)
  // through a 4x4 transpose: one float at a time, the stores were most of this loop's time. Each
  // element is put together in a register (stored in pieces and loaded whole, it waited for the
  // stores).
  const auto element_vector = [&](size_t i) {
    const size_t element = elements[i];
    if (element >= view.count) return _mm_loadu_ps(view.current);
    const uint8_t* at = view.base + view.stride * element;
    const __m128 zero = _mm_setzero_ps(), w = _mm_set_ss(1.f);  // (1, 0, 0, 0)
    if constexpr (kUnorm8) {
      // Bytes to 32-bit lanes, each divided by 255 as read_vertex_component does (the missing
      // bytes are 0: w gets 1 below).
      uint32_t bytes = 0;
      std::memcpy(&bytes, at, kSize);
      const __m128i none = _mm_setzero_si128();
      const __m128i words = _mm_unpacklo_epi16(_mm_unpacklo_epi8(_mm_cvtsi32_si128(static_cast<int>(bytes)), none), none);
      const __m128 v = _mm_div_ps(_mm_cvtepi32_ps(words), _mm_set1_ps(255.f));
      if constexpr (kSize == 4) return v;
      return _mm_or_ps(v, _mm_shuffle_ps(w, w, _MM_SHUFFLE(0, 1, 1, 1)));  // w = 1
    } else {
      const float* f = reinterpret_cast<const float*>(at);
      if constexpr (kSize == 4) return _mm_loadu_ps(f);
      if constexpr (kSize == 1) return _mm_shuffle_ps(_mm_load_ss(f), w, _MM_SHUFFLE(0, 1, 1, 0));  // (x, 0, 0, 1)
      const __m128 xy = _mm_loadl_pi(zero, reinterpret_cast<const __m64*>(f));
      if constexpr (kSize == 2) return _mm_movelh_ps(xy, _mm_shuffle_ps(w, w, _MM_SHUFFLE(1, 1, 0, 1)));  // (x, y, 0, 1)
      return _mm_movelh_ps(xy, _mm_unpacklo_ps(_mm_load_ss(f + 2), w));  // (x, y, z, 1)
    }
  };
  size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    __m128 c0 = element_vector(i), c1 = element_vector(i + 1), c2 = element_vector(i + 2), c3 = element_vector(i + 3);
    _MM_TRANSPOSE4_PS(c0, c1, c2, c3);  // cN: component N of the four
    float* out = lanes + (i / kLanes) * batch_floats + i % kLanes;
    _mm_storeu_ps(out, c0);
    _mm_storeu_ps(out + kLanes, c1);
    _mm_storeu_ps(out + 2 * kLanes, c2);
    _mm_storeu_ps(out + 3 * kLanes, c3);
  }
  for (; i < count; ++i) {
    alignas(16) float v[4];
    _mm_store_ps(v, element_vector(i));
    float* out = lanes + (i / kLanes) * batch_floats + i % kLanes;
    for (int c = 0; c < 4; ++c) out[c * kLanes] = v[c];
  }
}

template <bool kUnorm8>
void gather_direct_array_of_type(const DirectArrayView& view, const uint32_t* elements, size_t count, float* lanes,
                                 size_t batch_floats) {
  switch (view.size) {
    case 4: return gather_direct_array_of<4, kUnorm8>(view, elements, count, lanes, batch_floats);
    case 3: return gather_direct_array_of<3, kUnorm8>(view, elements, count, lanes, batch_floats);
    case 2: return gather_direct_array_of<2, kUnorm8>(view, elements, count, lanes, batch_floats);
    default: return gather_direct_array_of<1, kUnorm8>(view, elements, count, lanes, batch_floats);
  }
}

void gather_direct_array(const DirectArrayView& view, const uint32_t* elements, size_t count, float* lanes,
                         size_t batch_floats) {
  if (view.unorm8) return gather_direct_array_of_type<true>(view, elements, count, lanes, batch_floats);
  gather_direct_array_of_type<false>(view, elements, count, lanes, batch_floats);
}

// Each vertex's point size: the shader's (`from_shader`) or glPointSize's, clamped to the point
// parameters' range.
struct PointSizes {
  bool from_shader = false;
  float fixed = 1.f, min = 0.f, max = 1.f;
};

PointSizes point_sizes(const Context& ctx, const shader::Program& program) {
  const raster::PointParameters& pp = ctx.draw_state.point_params;
  return {ctx.programs.point_size_from_shader && program.writes_point_size(), ctx.draw_state.point_size, pp.size_min,
          pp.size_max};
}

// Runs the vertex shader over `vertices`: clip positions, clip distances, point sizes and edge
// flags into `out`, the varyings into `varyings` (program.varying_floats() per vertex); with
// `conventional_outputs` the other (fixed-function) fields of `out` start at zero, else they
// are left as they were. The uniforms are `draw`'s; texture lookups read `units`.
void run_vertex_shader(Context& ctx, const shader::Program& program, const raster::ShaderDraw& draw,
                       const std::array<raster::TextureUnit, raster::kMaxTextureImageUnits>& units,
                       const ShaderVertices& vertices, AttribSource source, const PointSizes& sizes,
                       bool conventional_outputs, TransformedVertices& transformed,
                       std::vector<float>& varyings) {
  const int slots = std::max(program.input_slots(), 1);
  const int nv = program.varying_floats();
  const int outputs = shader::kOutFirstVarying + nv;
  // Up to kMaxBlocksPerRun batches of 16 vertices run together (Program::run_vertex_batches).
  constexpr size_t kRunVertices = static_cast<size_t>(shader::kMaxBlocksPerRun) * kLanes;
  static_assert(raster::Renderer::kVerticesPerPiece % kRunVertices == 0);
  const size_t in_floats = static_cast<size_t>(slots) * 4 * kLanes, out_floats = static_cast<size_t>(outputs) * kLanes;
  const std::span<raster::ClipVertex> out = transformed.resize(vertices.size());
  // Only grows, as `transformed`: every vertex's varyings are written below.
  if (const size_t floats = vertices.size() * static_cast<size_t>(nv); varyings.size() < floats) varyings.resize(floats);
  VertexRunScratch& scratch = ctx.programs.vertex_run;
  const std::vector<InputFetch>& fetches = scratch.fetches;
  if (const StateKey key = ctx.state_key(); key != scratch.fetches_state || source != scratch.fetches_source) {
    input_fetches(ctx, program, source, slots, scratch.fetches);
    std::vector<bool> fetched(static_cast<size_t>(slots));
    for (const InputFetch& f : scratch.fetches) fetched[static_cast<size_t>(f.slot)] = true;
    scratch.fetches_fill_slots = std::find(fetched.begin(), fetched.end(), false) == fetched.end();
    scratch.fetches_state = key;
    scratch.fetches_source = source;
  }
  const uint32_t planes = enabled_clip_planes(ctx);
  const Context& state = ctx;
  // Array elements take their edge flags from the edge flag array only when it is enabled.
  const bool edge_flag_array = vertices.inputs.empty() && ctx.edge_flag_array.active();
  const float* const uniforms = draw.uniforms.data();
  // What the shader computes from uniforms alone, once for the draw's uniforms (not once per run).
  const float* const uniform_values = draw.vertex_uniform_values();
  const auto clamped_size = [&sizes](float size) { return std::clamp(std::isfinite(size) ? size : 1.f, sizes.min, sizes.max); };
  const float fixed_size = clamped_size(sizes.fixed);
  const bool one_piece = vertices.size() <= raster::Renderer::kVerticesPerPiece;  // run here, on this thread
  ctx.renderer().for_each_piece(vertices.size(), raster::Renderer::kVerticesPerPiece, [&](size_t begin, size_t end) {
    const raster::UnitTextureAccess textures(units);  // its sampler cache is one thread's
    // The shaders' modes (shader::ir::FlushDenormals), set once for the piece rather than by
    // each run (batches' denormals_flushed).
    const raster::ScopedFloatModes modes(raster::kShaderFloatModes);
    std::vector<float> piece_in, piece_result;
    std::vector<float>& in = one_piece ? scratch.in : piece_in;
    std::vector<float>& result = one_piece ? scratch.result : piece_result;
    in.resize(in_floats * shader::kMaxBlocksPerRun);
    result.resize(out_floats * shader::kMaxBlocksPerRun);
    for (size_t first = begin; first < end; first += kRunVertices) {
      const size_t count = std::min(kRunVertices, end - first);
      const int batch_count = static_cast<int>((count + kLanes - 1) / kLanes);
      // The slots no fetch writes hold zeros (the scratch's, from an earlier draw, too), and so
      // do the lanes past the last vertex then (their outputs are not read); the outputs start at
      // zero.
      if (!scratch.fetches_fill_slots && (count % kLanes != 0 || (one_piece && first == begin)))
        std::fill_n(in.begin(), in_floats * static_cast<size_t>(batch_count), 0.f);
      std::fill_n(result.begin(), out_floats * static_cast<size_t>(batch_count), 0.f);
      // Vertex i's component c of input slot `slot`.
      const auto input = [&](size_t i, int slot, int c) -> float& {
        return in[(i / kLanes) * in_floats + (static_cast<size_t>(slot) * 4 + c) * kLanes + i % kLanes];
      };
      if (vertices.inputs.empty()) {  // array elements: each input read straight from its array
        for (const InputFetch& f : fetches) {
          if (f.from_view) {
            gather_direct_array(f.view, vertices.elements.data() + first, count,
                               in.data() + static_cast<size_t>(f.slot) * 4 * kLanes, in_floats);
            continue;
          }
          if (f.location != 0 && !state.programs.arrays[f.location].active()) {
            // A disabled array: its current value for every vertex (fetched per vertex, it was a
            // tenth of this function in glmark2's build scene, whose texcoord array is off).
            const std::array<float, 4>& value = state.programs.current_attrib[f.location];
            for (size_t batch = 0; batch * kLanes < count; ++batch)
              for (int c = 0; c < 4; ++c) {
                float* const lanes = &input(batch * kLanes, f.slot, c);
                const size_t n = std::min<size_t>(kLanes, count - batch * kLanes);
                // Four lanes a store (this folder's -O2 leaves std::fill_n one float a store).
                const __m128 v = _mm_set1_ps(value[c]);
                size_t i = 0;
                for (; i + 4 <= n; i += 4) _mm_storeu_ps(lanes + i, v);
                std::fill_n(lanes + i, n - i, value[c]);
              }
            continue;
          }
          for (size_t i = 0; i < count; ++i) {
            float value[4];
            fetch_generic_element(state, f.location, vertices.elements[first + i], value);
            for (int c = 0; c < 4; ++c) input(i, f.slot, c) = value[c];
          }
        }
      } else {
        for (size_t i = 0; i < count; ++i) {
          const raster::VertexInput& v = vertices.inputs[first + i];
          for (const InputFetch& f : fetches) {
            float value[4];
            if (f.builtin != shader::BuiltinAttribute::None) builtin_input(v, f.builtin, value);
            else if (f.from_view) f.view.read(v.source, value);
            else fetch_generic(state, source, v, f.location, value);
            for (int c = 0; c < 4; ++c) input(i, f.slot, c) = value[c];
          }
        }
      }
      // Only the batches that run are made (default-initializing all of them was a `rep stos`
      // whose start-up cost showed in draws of a few vertices).
      alignas(shader::VertexBatch) std::byte batch_room[sizeof(shader::VertexBatch) * shader::kMaxBlocksPerRun];
      auto* const batches = reinterpret_cast<shader::VertexBatch*>(batch_room);
      for (int b = 0; b < batch_count; ++b)
        new (&batches[b]) shader::VertexBatch{
            .count = static_cast<int>(std::min<size_t>(kLanes, count - static_cast<size_t>(b) * kLanes)),
            .inputs = in.data() + static_cast<size_t>(b) * in_floats,
            .outputs = result.data() + static_cast<size_t>(b) * out_floats,
            .uniform_values = uniform_values,
            .denormals_flushed = true};
      program.run_vertex_batches(uniforms, &textures, batches, batch_count);
      for (size_t i = 0; i < count; ++i) {
        const float* r = result.data() + (i / kLanes) * out_floats;
        const size_t lane = i % kLanes;
        raster::ClipVertex& c = out[first + i];
        // A copy of a zero vertex: vector moves (assigning ClipVertex{} became `rep stos`, whose
        // start-up cost per vertex was a quarter of this function's time).
        static constexpr raster::ClipVertex kZero{};
        if (conventional_outputs) std::memcpy(&c, &kZero, sizeof c);
        std::fill(std::begin(c.clip_distance), std::end(c.clip_distance), 0.f);
        if (planes) {
          const glm::dvec4 clip_vertex(r[static_cast<size_t>(shader::kOutClipVertex + 0) * kLanes + lane],
                                       r[static_cast<size_t>(shader::kOutClipVertex + 1) * kLanes + lane],
                                       r[static_cast<size_t>(shader::kOutClipVertex + 2) * kLanes + lane],
                                       r[static_cast<size_t>(shader::kOutClipVertex + 3) * kLanes + lane]);
          for (uint32_t left = planes; left; left &= left - 1) {  // GL 2.0 2.12: planes test gl_ClipVertex
            const int p = __builtin_ctz(left);
            c.clip_distance[p] = static_cast<float>(glm::dot(state.extras.clip_planes[p], clip_vertex));
          }
        }
        c.edge_flag = !vertices.inputs.empty() ? vertices.inputs[first + i].edge_flag
                      : edge_flag_array        ? array_edge_flag(state, vertices.elements[first + i])
                                               : state.current_edge_flag;
        c.point_size = sizes.from_shader ? clamped_size(r[static_cast<size_t>(shader::kOutPointSize) * kLanes + lane])
                                         : fixed_size;
      }
      for (int b = 0; b < batch_count; ++b) {
        const float* lanes = result.data() + static_cast<size_t>(b) * out_floats;
        const size_t first_vertex = first + static_cast<size_t>(b) * kLanes;
        positions_from_lanes(lanes + static_cast<size_t>(shader::kOutPosition) * kLanes, batches[b].count,
                             out.data() + first_vertex);
        varyings_from_lanes(lanes + static_cast<size_t>(shader::kOutFirstVarying) * kLanes, batches[b].count, nv,
                            varyings.data() + first_vertex * static_cast<size_t>(nv));
      }
    }
  });
}

}  // namespace

namespace {

// Where a varying of the conventional (fixed-function) interface lives in a ClipVertex.
struct ConventionalVarying {
  float* front = nullptr;
  float* back = nullptr;
  int components = 0;
};

ConventionalVarying conventional(raster::ClipVertex& v, std::string_view name) {
  if (name == "gl_Color") return {v.color, v.back_color, 4};
  if (name == "gl_SecondaryColor") return {v.secondary, v.back_secondary, 3};
  if (name == "gl_FogFragCoord") return {&v.fog, nullptr, 1};
  if (name.starts_with("gl_TexCoord[") && name.size() == 14 && name[13] == ']') {
    const int unit = name[12] - '0';
    if (unit >= 0 && unit < raster::kMaxTextureUnits) return {v.texcoord[unit], nullptr, 4};
  }
  return {};
}

const LinkedProgram* program_in_use(Context& ctx) {
  const LinkedProgram* exec = ctx.programs.active();
  return exec && exec->program ? exec : nullptr;
}

// The draw's program, copy of the uniforms (built-ins filled from GL state) and facing; null
// after an error. The last draw's when all are the same, bit for bit (a uniform's zero that
// changed sign is a change): its record then serves this draw too.
std::shared_ptr<const raster::ShaderDraw> shader_draw_for(Context& ctx, const LinkedProgram& exec, bool two_side) {
  if (!exec.sampler_conflict.empty()) {
    ctx.record_error(GL_INVALID_OPERATION, exec.sampler_conflict);
    return nullptr;
  }
  std::vector<float>& values = ctx.programs.draw_uniforms;
  values.assign(exec.values.begin(), exec.values.end());
  fill_builtin_uniforms(ctx, *exec.program, values);
  std::shared_ptr<const raster::ShaderDraw>& last = ctx.programs.last_shader_draw;
  if (last && last->program == exec.program && last->two_side == two_side && last->uniforms.size() == values.size() &&
      (values.empty() || std::memcmp(last->uniforms.data(), values.data(), values.size() * sizeof(float)) == 0))
    return last;
  std::shared_ptr<raster::ShaderDraw> draw = ctx.programs.shader_draws.take(values.size());
  draw->program = exec.program;
  draw->uniforms.assign(values.begin(), values.end());
  draw->two_side = two_side;
  last = draw;
  return draw;
}

// The state of a draw with `exec`: ctx.programs.draw_state, worked out again only when the
// state changed (StateKey: copying the context's draw state, filling the built-in uniforms and
// taking the samplers' textures were a tenth of a small draw on the calling thread); null
// after an error.
const raster::DrawState* program_draw_state(Context& ctx, const LinkedProgram& exec) {
  ProgramState& ps = ctx.programs;
  const StateKey key = ctx.state_key();
  if (key == ps.draw_state_prepared && ps.draw_state.shader) return &ps.draw_state;
  ps.draw_state_prepared = {};
  std::shared_ptr<const raster::ShaderDraw> shader_draw = shader_draw_for(ctx, exec, ps.two_side);
  if (!shader_draw) return nullptr;
  raster::DrawState& state = ps.draw_state;
  state = ctx.draw_state;
  snapshot_sampler_textures(ctx, *exec.program, shader_draw->uniforms, state);
  state.viewport = ctx.viewport;
  state.cull_face = ctx.enable_cull;
  // Each vertex brings its size: the shader's, or glPointSize (no distance attenuation
  // without eye coordinates), clamped to the point parameters' range.
  state.point_params.size_per_vertex = true;
  state.point_params.attenuation[0] = 1.f;
  state.point_params.attenuation[1] = state.point_params.attenuation[2] = 0.f;
  state.shader = std::move(shader_draw);
  state.clip_planes = enabled_clip_planes(ctx);  // the planes test gl_ClipVertex (run_vertex_shader)
  // Vertex-shader texture lookups read the same (usable) images the fragments will.
  raster::drop_unusable_textures(state.texture_units);
  ps.draw_state_prepared = key;
  return &state;
}

void draw_or_feed_back(Context& ctx, const raster::DrawState& state, raster::Primitive primitive,
                       std::span<const raster::ClipVertex> vertices, std::span<const uint32_t> indices,
                       const float* varyings) {
  if (ctx.render_mode.mode != GL_RENDER) return select_feedback_draw(ctx, state, primitive, vertices, indices);
  ctx.render_to_draw_buffers([&] {
    // gl_FragData[i] goes to the colour buffer DRAW_BUFFERi selects, gl_FragColor (colour 0) to all.
    const shader::Program* program = state.shader ? state.shader->program.get() : nullptr;
    const int output = program && program->broadcasts_color() ? 0 : ctx.draw_pass_output();
    if (!state.shader || state.shader->color_output == output)
      return ctx.renderer().draw(state, primitive, vertices, indices, varyings);
    raster::DrawState pass = state;
    auto shader = std::make_shared<raster::ShaderDraw>(*state.shader);
    shader->color_output = output;
    pass.shader = std::move(shader);
    ctx.renderer().draw(pass, primitive, vertices, indices, varyings);
  });
}

}  // namespace

bool draw_with_program(Context& ctx, raster::Primitive primitive, const ShaderVertices& vertices,
                       std::span<const uint32_t> indices, AttribSource source) {
  const LinkedProgram* exec = program_in_use(ctx);
  if (!exec || !exec->vertex_shader || !exec->fragment_shader) return false;
  const shader::Program& program = *exec->program;
  const raster::DrawState* prepared = program_draw_state(ctx, *exec);
  if (!prepared) return true;
  const raster::DrawState& state = *prepared;
  std::vector<float>& varyings = ctx.programs.draw_varyings;
  // Feedback reports the fixed-function colours and coordinates: zero (the varyings are not mapped back).
  const bool conventional_outputs = ctx.render_mode.mode != GL_RENDER;
  run_vertex_shader(ctx, program, *state.shader, state.texture_units, vertices, source, point_sizes(ctx, program),
                    conventional_outputs, ctx.transformed, varyings);
  draw_or_feed_back(ctx, state, primitive, ctx.transformed.vertices(), indices, varyings.data());
  return true;
}

bool run_vertex_program_only(Context& ctx, std::span<const raster::VertexInput> vertices, AttribSource source,
                             TransformedVertices& transformed) {
  const LinkedProgram* exec = program_in_use(ctx);
  if (!exec || !exec->vertex_shader || exec->fragment_shader) return false;
  const shader::Program& program = *exec->program;
  const std::shared_ptr<const raster::ShaderDraw> shader_draw = shader_draw_for(ctx, *exec, ctx.programs.two_side);
  if (!shader_draw) {
    transformed.resize(0);
    return true;
  }
  raster::DrawState state = ctx.draw_state;
  snapshot_sampler_textures(ctx, program, shader_draw->uniforms, state);
  raster::drop_unusable_textures(state.texture_units);
  std::vector<float>& varyings = ctx.programs.draw_varyings;
  run_vertex_shader(ctx, program, *shader_draw, state.texture_units, {vertices, {}},
                    source, point_sizes(ctx, program), true, transformed, varyings);
  const std::span<raster::ClipVertex> out = transformed.vertices();
  const int nv = program.varying_floats();
  for (size_t i = 0; i < out.size(); ++i) {
    raster::ClipVertex& v = out[i];
    const float* in = varyings.data() + i * static_cast<size_t>(nv);
    bool has_back_color = false, has_back_secondary = false;
    for (const shader::Varying& var : program.varyings()) {
      const ConventionalVarying c = conventional(v, var.name);
      const int n = std::min(c.components, var.components);
      for (int k = 0; k < n && var.offset + k < nv; ++k) c.front[k] = in[var.offset + k];
      if (!c.back || var.back_offset < 0) continue;
      for (int k = 0; k < n && var.back_offset + k < nv; ++k) c.back[k] = in[var.back_offset + k];
      (c.back == v.back_color ? has_back_color : has_back_secondary) = true;
    }
    // GL 2.0 2.15.3: the colours are clamped to [0, 1] before rasterization.
    for (float* c : {v.color, v.back_color}) std::transform(c, c + 4, c, [](float x) { return std::clamp(x, 0.f, 1.f); });
    for (float* c : {v.secondary, v.back_secondary}) std::transform(c, c + 3, c, [](float x) { return std::clamp(x, 0.f, 1.f); });
    if (!has_back_color || !ctx.programs.two_side) std::copy(v.color, v.color + 4, v.back_color);
    if (!has_back_secondary || !ctx.programs.two_side) std::copy(v.secondary, v.secondary + 3, v.back_secondary);
  }
  ctx.draw_state.point_params.size_per_vertex = true;  // the sizes are the shader's or glPointSize
  ctx.fixed_function_prepared = {};
  return true;
}

bool draw_fragment_program_only(Context& ctx, raster::Primitive primitive, std::span<const raster::ClipVertex> vertices,
                                std::span<const uint32_t> indices) {
  const LinkedProgram* exec = program_in_use(ctx);
  if (!exec || exec->vertex_shader || !exec->fragment_shader) return false;
  const shader::Program& program = *exec->program;
  // The fixed-function stage computed both colours; the back ones apply with two-sided lighting.
  const std::shared_ptr<const raster::ShaderDraw> shader_draw =
      shader_draw_for(ctx, *exec, ctx.lighting.enabled && ctx.lighting.two_side);
  if (!shader_draw) return true;
  raster::DrawState state = ctx.draw_state;
  snapshot_sampler_textures(ctx, program, shader_draw->uniforms, state);
  state.shader = shader_draw;
  const int nv = program.varying_floats();
  std::vector<float>& varyings = ctx.programs.draw_varyings;
  varyings.assign(vertices.size() * static_cast<size_t>(nv), 0.f);
  for (size_t i = 0; i < vertices.size(); ++i) {
    raster::ClipVertex v = vertices[i];
    float* out = varyings.data() + i * static_cast<size_t>(nv);
    for (const shader::Varying& var : program.varyings()) {
      const ConventionalVarying c = conventional(v, var.name);
      const int n = std::min(c.components, var.components);
      for (int k = 0; k < n && var.offset + k < nv; ++k) out[var.offset + k] = c.front[k];
      if (c.components == 3 && var.components == 4 && var.offset + 3 < nv) out[var.offset + 3] = 1.f;
      if (!c.back || var.back_offset < 0) continue;
      for (int k = 0; k < n && var.back_offset + k < nv; ++k) out[var.back_offset + k] = c.back[k];
      if (c.components == 3 && var.components == 4 && var.back_offset + 3 < nv) out[var.back_offset + 3] = 1.f;
    }
  }
  draw_or_feed_back(ctx, state, primitive, vertices, indices, varyings.data());
  return true;
}

}  // namespace pineda
