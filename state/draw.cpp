#include "state/draw.h"

#include <algorithm>

#include <glm/gtc/matrix_inverse.hpp>

#include "raster/renderer.h"
#include "state/context.h"
#include "state/enum_translate.h"
#include "state/programs/program_draw.h"
#include "state/point_parameters.h"
#include "state/select_feedback.h"
#include "state/vertex_arrays/index_runs.h"
#include "state/vertex_arrays/vertex_fetch.h"
#include "state/vertex_extras_snapshot.h"

namespace pineda {
namespace {

bool is_identity(const glm::mat4& m) { return m == glm::mat4(1.f); }

// ctx.draw_transform for a draw reading `texture_units` units: every field the vertex stage reads
// (the lights only when lighting is on) set from the context.
raster::Transform& build_transform(Context& ctx, int texture_units) {
  raster::Transform& t = ctx.draw_transform;
  const glm::dmat4& mv = ctx.modelview.top();
  t.modelview = glm::mat4(mv);
  t.modelview_projection = glm::mat4(ctx.projection.top() * mv);
  if (ctx.lighting.enabled)
    t.lighting = ctx.lighting;
  else
    t.lighting.enabled = false;
  t.normal_matrix = glm::mat3(1.f);
  t.normalize = false;
  t.rescale_factor = 1.f;
  if (ctx.lighting.enabled || texgen_needs_normal(ctx, texture_units)) {
    t.normal_matrix = glm::mat3(glm::inverseTranspose(glm::dmat3(mv)));
    t.normalize = ctx.normalize;
    if (ctx.rescale_normal && !ctx.normalize) {
      // GL: the factor is 1 / length of the third row of the inverse modelview's upper 3x3.
      const glm::dmat3 inv = glm::inverse(glm::dmat3(mv));
      const double len = glm::length(glm::dvec3(inv[0][2], inv[1][2], inv[2][2]));
      t.rescale_factor = len > 0.0 ? static_cast<float>(1.0 / len) : 1.f;
    }
  }
  t.texture_units = texture_units;
  for (int u = 0; u < texture_units; ++u) {
    t.texture_matrix[u] = glm::mat4(ctx.texture_matrix[u].top());
    t.texture_matrix_identity[u] = is_identity(t.texture_matrix[u]);
  }
  snapshot_vertex_extras(ctx, t, texture_units);
  snapshot_point_parameters(ctx, t);
  return t;
}

// Fills the draw snapshot's texture units; returns how many units the rasterizer reads.
int snapshot_textures(Context& ctx) {
  int used = 0;
  for (int u = 0; u < raster::kMaxTextureUnits; ++u) {
    TextureUnitState& unit = ctx.texture_units[u];
    raster::TextureUnit& out = ctx.draw_state.texture_units[u];
    out.image.reset();
    if (!unit.any_target_enabled()) continue;
    TextureObject* tex = nullptr;
    for (TexTarget kind : {TexTarget::Cube, TexTarget::Rect, TexTarget::T3D, TexTarget::T2D, TexTarget::T1D}) {  // GL 1.3 3.8.15, ARB_texture_rectangle
      if (!enabled_flag(unit, kind)) continue;
      tex = &ctx.textures.get_or_create(bound_name(unit, kind), binding_enum(kind));
      break;
    }
    if (!tex) continue;
    const bool rendered_into = attached_to_draw_framebuffer(ctx, *tex);
    if (rendered_into) resolve_rendered_textures(ctx);  // a feedback loop samples what was rendered before this draw
    const TexParams* sampling = unit.sampler ? &unit.sampler->params : nullptr;
    out.image = tex->snapshot(sampling, rendered_into);
    if (!out.image) continue;
    out.sampler = tex->sampler(sampling);
    out.sampler.lod_bias =
        std::clamp(out.sampler.lod_bias + unit.env.lod_bias, -kMaxTextureLodBias, kMaxTextureLodBias);
    out.env_mode = raster_env_mode(unit.env);
    if (out.env_mode == raster::TexEnvMode::Combine) out.combine = raster_combine(unit.env);
    std::copy(unit.env.color, unit.env.color + 4, out.env_color);
    used = u + 1;
  }
  return used;
}

// Transform and lighting of a draw's vertices into ctx.transformed, in pieces on the renderer's
// threads (each vertex alone: the pieces do not change a value).
void transform_in_pieces(Context& ctx, const raster::Transform& transform, std::span<const raster::VertexInput> vertices) {
  const std::span<raster::ClipVertex> out = ctx.transformed.resize(vertices.size());
  ctx.renderer().for_each_piece(vertices.size(), raster::Renderer::kVerticesPerPiece, [&](size_t begin, size_t end) {
    raster::transform_vertices(transform, vertices.subspan(begin, end - begin), out.subspan(begin, end - begin));
  });
}

}  // namespace

raster::ClipVertex transform_single_vertex(Context& ctx, const raster::VertexInput& vertex) {
  const raster::Transform& transform = build_transform(ctx, raster::kMaxTextureUnits);
  std::vector<raster::ClipVertex> out;
  raster::transform_vertices(transform, std::span(&vertex, 1), out);
  return out[0];
}

const raster::DrawState& fragment_snapshot(Context& ctx) {
  snapshot_textures(ctx);
  ctx.draw_state.viewport = ctx.viewport;
  return ctx.draw_state;
}

namespace {

// A fixed-function draw's state: the texture units' snapshot, per-vertex point sizes, the
// viewport, culling and the vertex transform, which it returns (for every unit's coordinates
// with a `program`, whose fragment shader may read them as gl_TexCoord[i]).
raster::Transform& prepare_fixed_function(Context& ctx, bool program) {
  // Worked out once while the state stays the same (the transform's matrix products and the
  // texture snapshots were a tenth of a small draw's time on the calling thread).
  const StateKey key = ctx.state_key();
  if (key == ctx.fixed_function_prepared) return ctx.draw_transform;
  ctx.fixed_function_prepared = key;
  const int texture_units = snapshot_textures(ctx);
  ctx.draw_state.point_params.size_per_vertex = ctx.point_size_array.active();
  ctx.draw_state.viewport = ctx.viewport;
  ctx.draw_state.cull_face = ctx.enable_cull;
  // Feedback reports unit 0's coordinates even when no texture is enabled.
  const bool feedback = ctx.render_mode.mode == GL_FEEDBACK;
  return build_transform(ctx, program ? raster::kMaxTextureUnits : feedback ? std::max(texture_units, 1) : texture_units);
}

// The draw after the program check: the fixed-function vertex stage (or a vertex-only
// program's) into ctx.transformed by `transform_step(transform)` unless such a program ran,
// then the primitives to the renderer (or feedback).
template <typename TransformStep>
void draw_fixed_function(Context& ctx, raster::Primitive primitive, std::span<const uint32_t> indices,
                         const std::function<bool()>& run_vertex_program, TransformStep transform_step) {
  // OpenGL ES 2.0 has no fixed function: without a program the results are undefined (ES 2.0
  // 2.15); Pineda draws nothing.
  if (ctx.es2()) return;
  const bool program = ctx.programs.active() != nullptr;  // with one stage only (program_draw.h)
  raster::Transform& transform = prepare_fixed_function(ctx, program);
  if (!(program && run_vertex_program())) transform_step(transform);
  raster::DrawState& state = ctx.draw_state;
  const std::span<const raster::ClipVertex> transformed = ctx.transformed.vertices();
  if (program && draw_fragment_program_only(ctx, primitive, transformed, indices)) return;
  if (ctx.render_mode.mode != GL_RENDER) return select_feedback_draw(ctx, state, primitive, transformed, indices);
  ctx.render_to_draw_buffers([&] { ctx.renderer().draw(state, primitive, transformed, indices); });
}

}  // namespace

void draw_vertices(Context& ctx, GLenum mode, std::span<const raster::VertexInput> vertices,
                   std::span<const uint32_t> indices, std::span<const Context::MaterialChange> materials,
                   AttribSource generic_source) {
  if (!ctx.draw_drawable() || vertices.empty()) return;
  raster::Primitive primitive;
  if (!to_primitive(mode, primitive)) return;
  // A program reads gl_FrontMaterial/gl_BackMaterial once per draw: the material in effect at
  // glBegin; materials set inside the primitive only light fixed-function vertices (as Mesa).
  struct MaterialAtBegin {
    Context& ctx;
    raster::Material front, back;
    bool swapped;
    ~MaterialAtBegin() {
      if (swapped) ctx.lighting.front = front, ctx.lighting.back = back;
    }
  } restore{ctx, ctx.lighting.front, ctx.lighting.back, ctx.programs.active() && !materials.empty()};
  if (restore.swapped) ctx.lighting.front = materials[0].front, ctx.lighting.back = materials[0].back;
  if (ctx.programs.active() && draw_with_program(ctx, primitive, {vertices, {}}, indices, generic_source)) return;
  const auto run_vertex_program = [&] { return run_vertex_program_only(ctx, vertices, generic_source, ctx.transformed); };
  draw_fixed_function(ctx, primitive, indices, run_vertex_program, [&](raster::Transform& transform) {
    if (materials.empty() || !ctx.lighting.enabled) return transform_in_pieces(ctx, transform, vertices);
    // Each run of vertices is lit with the material in effect when they were specified.
    ctx.fixed_function_prepared = {};  // (the transform's materials change)
    const std::span<raster::ClipVertex> out = ctx.transformed.resize(vertices.size());
    std::vector<raster::ClipVertex> run_out;
    for (size_t i = 0; i < materials.size(); ++i) {
      const size_t first = std::min(materials[i].first, vertices.size());
      const size_t end = i + 1 < materials.size() ? std::min(materials[i + 1].first, vertices.size()) : vertices.size();
      if (first >= end) continue;
      transform.lighting.front = materials[i].front;
      transform.lighting.back = materials[i].back;
      raster::transform_vertices(transform, vertices.subspan(first, end - first), run_out);
      std::copy(run_out.begin(), run_out.end(), out.begin() + first);
    }
  });
}

namespace {

constexpr size_t kFetchRun = 256;  // fetched vertices transformed while they are in the cache

// Vertices [0, count) of a draw fetched by fetch(first, n, room) (n <= kFetchRun vertices into
// `room`) and transformed into `out`, kFetchRun at a time, in pieces on the renderer's threads.
template <typename Fetch>
void fetch_and_transform(Context& ctx, const raster::Transform& transform, size_t count, const Fetch& fetch,
                         std::span<raster::ClipVertex> out) {
  const auto run = [&](size_t first, size_t n, raster::VertexInput* room) {
    fetch(first, n, room);
    raster::transform_vertices(transform, std::span(room, n), out.subspan(first, n));
  };
  if (count <= kFetchRun) {  // one run on this thread, in the context's room (no allocation)
    if (ctx.fetched.size() < count) ctx.fetched.resize(count);  // only grows
    return run(0, count, ctx.fetched.data());
  }
  ctx.renderer().for_each_piece(count, raster::Renderer::kVerticesPerPiece, [&](size_t begin, size_t end) {
    std::vector<raster::VertexInput> fetched(std::min(kFetchRun, end - begin));
    for (size_t first = begin; first < end; first += kFetchRun)
      run(first, std::min(kFetchRun, end - first), fetched.data());
  });
}

// The vertices of one run of a draw in runs (draw_in_runs).
constexpr size_t kRunVertices = 4096;

// Vertices per primitive of the modes whose primitives are independent of each other (assembly
// decides nothing for the draw as a whole: quads take their diagonal from every vertex), else 0.
size_t independent_group(raster::Primitive primitive) {
  switch (primitive) {
    case raster::Primitive::Points: return 1;
    case raster::Primitive::Lines: return 2;
    case raster::Primitive::Triangles: return 3;
    default: return 0;
  }
}

// Whether a fixed-function draw of `count` array vertices goes to the renderer in runs: a large
// draw of independent primitives that is rendered once (not fed back, not to two buffers), by a
// renderer of one thread. With more, the whole draw's vertices are transformed on all of them
// before binning starts, where a run's are the calling thread's alone while the pool rasterizes
// the scene before (small_tris with two threads: 8-13% slower in runs, first frame aside).
bool draws_in_runs(Context& ctx, raster::Primitive primitive, size_t count) {
  return count > kRunVertices && independent_group(primitive) && !ctx.programs.active() && !ctx.es2() &&
         ctx.render_mode.mode == GL_RENDER && ctx.renders_draw_buffers_in_one_pass() && ctx.renderer().threads() == 1;
}

// draw_fixed_function for a draw that draws_in_runs: each run of its primitives is fetched,
// transformed and drawn in turn (the same primitives in the same order, so the same pixels).
void draw_in_runs(Context& ctx, raster::Primitive primitive, const ArrayVertices& vertices,
                  std::span<const uint32_t> indices) {
  const raster::Transform& transform = prepare_fixed_function(ctx, false);
  const raster::DrawState& state = ctx.draw_state;
  const size_t group = independent_group(primitive);
  const auto draw_run = [&](std::span<const uint32_t> run_indices) {
    const std::span<const raster::ClipVertex> transformed = ctx.transformed.vertices();
    ctx.render_to_draw_buffers([&] { ctx.renderer().draw(state, primitive, transformed, run_indices); });
  };
  if (indices.empty()) {
    const size_t run_length = kRunVertices / group * group;
    for (size_t first = 0; first < vertices.count; first += run_length) {
      const size_t n = std::min(run_length, vertices.count - first);
      fetch_and_transform(ctx, transform, n,
                          [&](size_t begin, size_t count, raster::VertexInput* room) {
                            vertices.fetch(first + begin, first + begin + count, room);
                          },
                          ctx.transformed.resize(n));
      draw_run({});
    }
    return;
  }
  for (size_t position = 0; position < indices.size();) {
    position = ctx.index_runs.next(indices, position, group, kRunVertices, vertices.count);
    const std::span<const uint32_t> run_vertices = ctx.index_runs.vertices();
    if (run_vertices.empty()) continue;
    // Consecutive vertices (most of a mesh's new ones) are fetched together.
    fetch_and_transform(ctx, transform, run_vertices.size(),
                        [&](size_t begin, size_t count, raster::VertexInput* room) {
                          for (size_t i = begin, end = begin + count; i < end;) {
                            size_t next = i + 1;
                            while (next < end && run_vertices[next] == run_vertices[next - 1] + 1) ++next;
                            vertices.fetch(run_vertices[i], size_t{run_vertices[next - 1]} + 1, room + (i - begin));
                            i = next;
                          }
                        },
                        ctx.transformed.resize(run_vertices.size()));
    draw_run(ctx.index_runs.run_indices());
  }
}

}  // namespace

void draw_array_vertices(Context& ctx, GLenum mode, const ArrayVertices& vertices, std::span<const uint32_t> indices) {
  if (!ctx.held_draws.elements.empty()) draw_held_back(ctx);  // they come first
  if (!ctx.draw_drawable() || vertices.count == 0) return;
  if (ctx.programs.active() && vertex_shader_reads_generic_attributes_only(ctx)) {
    // The shader reads each input straight from its array: no vertex is fetched before.
    raster::Primitive primitive;
    if (!to_primitive(mode, primitive)) return;
    std::vector<uint32_t>& elements = ctx.fetched_elements;
    elements.resize(vertices.count);
    vertices.elements(0, vertices.count, elements.data());
    if (draw_with_program(ctx, primitive, {{}, elements}, indices, AttribSource::Arrays)) return;
  }
  if (ctx.programs.active()) {  // every stage of a program reads the whole draw's vertices
    if (ctx.fetched.size() < vertices.count) ctx.fetched.resize(vertices.count);  // only grows
    const std::span<raster::VertexInput> all(ctx.fetched.data(), vertices.count);
    ctx.renderer().for_each_piece(vertices.count, raster::Renderer::kVerticesPerPiece,
                                  [&](size_t begin, size_t end) { vertices.fetch(begin, end, all.data() + begin); });
    return draw_vertices(ctx, mode, all, indices, {}, AttribSource::Arrays);
  }
  raster::Primitive primitive;
  if (!to_primitive(mode, primitive)) return;
  if (draws_in_runs(ctx, primitive, vertices.count)) return draw_in_runs(ctx, primitive, vertices, indices);
  draw_fixed_function(ctx, primitive, indices, [] { return false; }, [&](const raster::Transform& transform) {
    fetch_and_transform(ctx, transform, vertices.count,
                        [&](size_t first, size_t n, raster::VertexInput* room) { vertices.fetch(first, first + n, room); },
                        ctx.transformed.resize(vertices.count));
  });
}

}  // namespace pineda
