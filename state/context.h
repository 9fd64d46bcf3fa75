// The GL context: all GL state and objects, error recording, and the bridge to raster/.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <array>
#include <concepts>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "raster/draw_state.h"
#include "raster/renderer.h"
#include "raster/vertex.h"
#include "raster/vertex_transform.h"
#include "state/accum.h"
#include "state/attrib_stack.h"
#include "state/buffers/buffer_object.h"
#include "state/color_index.h"
#include "state/debug/debug_output.h"
#include "state/lists/display_list.h"
#include "state/draw_buffer_list.h"
#include "state/gl_error.h"
#include "state/multisample.h"
#include "state/drawable.h"
#include "state/evaluators/evaluator.h"
#include "state/framebuffers/framebuffer_object.h"
#include "state/pixels/pixel_state.h"
#include "state/programs/program_state.h"
#include "state/query_object.h"
#include "state/select_feedback.h"
#include "state/share_group.h"
#include "state/state_key.h"
#include "state/stencil_faces.h"
#include "state/textures/tex_env_state.h"
#include "state/transformed_vertices.h"
#include "state/vertex_arrays/held_draws.h"
#include "state/vertex_arrays/index_runs.h"
#include "state/vertex_arrays/vertex_fetch_plan.h"
#include "state/textures/texture_object.h"
#include "state/vertex_extras_state.h"
#include "state/vertex_arrays/vertex_array_object.h"

namespace pineda {

struct ContextAttribs {
  int major = 1, minor = 1;
  bool gles = false;
  bool debug = false;  // a debug context (GLX_CONTEXT_DEBUG_BIT_ARB, EGL_CONTEXT_OPENGL_DEBUG)
  // What EGL/GLX asked for: robust buffer access (which every Pineda context has: no access
  // leaves its object) and the reset notification strategy (no context is ever reset).
  bool robust_access = false;
  bool lose_context_on_reset = false;
  int threads = 0;  // 0: PINEDA_THREADS or one per core
};

struct MatrixStack {
  std::vector<glm::dmat4> stack{glm::dmat4(1.0)};
  size_t max_depth = 32;
  glm::dmat4& top() { return stack.back(); }
  const glm::dmat4& top() const { return stack.back(); }
};

struct PixelStore {
  GLint alignment = 4, row_length = 0, skip_rows = 0, skip_pixels = 0;
  GLint image_height = 0, skip_images = 0;  // 3D images only
  GLboolean swap_bytes = GL_FALSE, lsb_first = GL_FALSE;
  // PIXEL_PACK_BUFFER / PIXEL_UNPACK_BUFFER (state/buffers/pixel_buffer.h): kept with the pixel store
  // state, as PushClientAttrib saves it.
  std::shared_ptr<BufferObject> buffer;
};

// What glPushClientAttrib saves; glPopClientAttrib restores the groups of `mask` only.
struct ClientAttribFrame {
  GLbitfield mask = 0;
  PixelStore pack, unpack;
  // The vertex-array group: the bound vertex array object (as Mesa saves it), its arrays, and
  // the two bindings a vertex array object does not hold.
  GLuint vertex_array_binding = 0;
  VertexArrayGroup arrays;
  std::shared_ptr<BufferObject> array_buffer;
  GLuint client_active_texture = 0;
};

struct TextureUnitState {
  bool enabled_2d = false, enabled_1d = false;
  GLuint bound_2d = 0, bound_1d = 0;
  bool enabled_3d = false, enabled_cube = false;
  GLuint bound_3d = 0, bound_cube = 0;
  bool enabled_rect = false;
  GLuint bound_rect = 0;
  bool any_target_enabled() const { return enabled_1d || enabled_2d || enabled_3d || enabled_cube || enabled_rect; }
  TexEnvState env;
  // The sampler object bound to the unit (glBindSampler), or none.
  std::shared_ptr<SamplerObject> sampler;
  GLuint sampler_name = 0;
  float current_texcoord[4] = {0, 0, 0, 1};
  ClientArray texcoord_array;
};

class Context {
 public:
  // `share` is the group of the context given as share list; null starts a new group.
  explicit Context(const ContextAttribs& attribs, std::shared_ptr<ShareGroup> share = nullptr);
  ~Context();

  const ContextAttribs& attribs() const { return attribs_; }
  const std::shared_ptr<ShareGroup>& share_group() const { return share_group_; }
  // An OpenGL ES 1.x context: the ES 1.1 subset of the API, with its enums (glapi/).
  bool es1() const { return attribs_.gles && attribs_.major == 1; }
  // An OpenGL ES 2.0 context: the ES 2.0 subset (glapi/), shaders only (no fixed function),
  // GLSL ES 1.00, generic attribute 0 not the position (state/es2/).
  bool es2() const { return attribs_.gles && attribs_.major >= 2; }
  // Whether the active texture unit has fixed-function state (environment, texgen, enables,
  // texture matrix, coordinate set); texture image units past MAX_TEXTURE_UNITS have bindings
  // only, and the fixed-function calls give GL_INVALID_OPERATION there (GL 2.0 2.7, 3.8).
  bool fixed_function_texture_unit() const { return active_texture < raster::kMaxTextureUnits; }

  // Window-system binding (driver/). A null drawable is a surfaceless context.
  void make_current(Drawable* draw, Drawable* read);
  void release_current();
  // The buffers drawn into and read from: the bound framebuffer objects' views, or the
  // window-system drawables.
  Drawable* draw_drawable() const { return fbo_draw_ ? fbo_draw_ : draw_; }
  Drawable* read_drawable() const { return fbo_read_ ? fbo_read_ : read_; }
  Drawable* window_draw_drawable() const { return draw_; }
  Drawable* window_read_drawable() const { return read_; }
  // framebuffers/: the views of the bound framebuffer objects (null: the window's).
  void set_framebuffer_views(Drawable* draw, Drawable* read);
  // The driver calls this when a bound drawable's buffers were replaced (resize, swap).
  void drawable_changed();
  // Runs `render` (renderer calls) once per colour buffer that glDrawBuffer selects
  // (draw_buffers.cpp).
  void render_to_draw_buffers(raster::FunctionRef<void()> render);
  // Whether render_to_draw_buffers runs `render` once (else twice: a window's front and back).
  bool renders_draw_buffers_in_one_pass() const;
  // While `render` runs for one colour buffer: the index i of the first DRAW_BUFFERi that
  // selects it, so a fragment shader's gl_FragData[i] goes there.
  int draw_pass_output() const { return draw_pass_output_; }
  // The read drawable's buffers with the colour buffer that glReadBuffer selects.
  raster::Framebuffer read_framebuffer() const;

  // Errors: the first one is kept until glGetError reads it. `why` names the argument and
  // the rule it broke, for the debug message (GL_KHR_debug, PINEDA_DEBUG=1).
  void record_error(GLenum error, std::string_view why = {}) {
    ++errors_recorded_;
    if (error_ == GL_NO_ERROR) error_ = error;
    if (debug.reports_errors()) debug.report_error(current_call, error, why);
  }
  // The same, with a message made only when something reports it (a lambda returning a string).
  template <class MakeWhy>
    requires std::invocable<MakeWhy>
  void record_error(GLenum error, MakeWhy&& make_why) {
    ++errors_recorded_;
    if (error_ == GL_NO_ERROR) error_ = error;
    if (debug.reports_errors()) debug.report_error(current_call, error, make_why());
  }
  // The same for an error a check returned with its rule.
  void record_error(GlError error) { record_error(error.code, std::string_view(error.why)); }
  // Counts every recorded error, kept or not: a wrapper compares it around a call to learn
  // whether the call failed (state/es1/).
  uint64_t errors_recorded() const { return errors_recorded_; }
  GLenum take_error() {
    GLenum e = error_;
    error_ = GL_NO_ERROR;
    return e;
  }
  bool inside_begin_end() const { return in_begin_end; }

  // The state as StateKey counts it. A GL call that may change state counts itself (glapi/, with
  // `shared`: it holds the share group's lock); so does whatever changes state outside such calls.
  StateKey state_key() const { return {state_changes_, share_group_->changes.load(std::memory_order_relaxed)}; }
  void count_state_call(bool shared) {
    if (!held_draws.elements.empty()) draw_held_back(*this);
    ++state_changes_;
    if (shared) share_group_->changes.store(share_group_->changes.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  }
  void note_state_changed() {
    if (!held_draws.elements.empty()) draw_held_back(*this);
    ++state_changes_;
  }

  // Display-list compilation (glNewList .. glEndList).
  bool compiling_list() const { return compilation.name != 0; }
  bool executing_while_compiling() const { return compilation.mode == GL_COMPILE_AND_EXECUTE; }
  void record_list_command(ListCommand command) { compilation.list->commands.push_back(std::move(command)); }

  raster::Renderer& renderer() { return *renderer_; }
  // The queued rendering done; the caller may then write the framebuffer's memory.
  void finish() {
    if (!held_draws.elements.empty()) draw_held_back(*this);
    renderer_->flush();
  }
  // The same for a caller that only reads it (glFinish, swaps, glReadPixels): tiles known to
  // hold a clear's value stay known (raster/cleared_tiles.h).
  void finish_for_reading() {
    if (!held_draws.elements.empty()) draw_held_back(*this);
    renderer_->flush_for_reading();
  }

  // ---- state, read and written by the state/ implementation files ----
 private:
  std::shared_ptr<ShareGroup> share_group_;  // first: the references below point into it

 public:
  // The GL function being executed ("glTexImage2D"), set by each entry point for messages.
  const char* current_call = "";
  DebugOutput debug;

  bool in_begin_end = false;
  GLenum begin_mode = GL_POINTS;
  std::vector<raster::VertexInput> immediate;
  VertexFetchPlan vertex_fetch_plan;  // the current array draw's (api_arrays.cpp's array_elements)
  StateKey vertex_fetch_planned;      // the state it was built from
  // The state and how many elements every enabled array's buffer held then (arrays_ready,
  // buffers/buffer_draw.cpp).
  struct ArraysReady {
    StateKey state;
    size_t elements = 0;
    bool client_memory = false;  // an enabled array reads client memory (no buffer object)
  } arrays_known_ready;
  HeldDraws held_draws;  // state/vertex_arrays/held_draws.h
  std::vector<raster::VertexInput> fetched;   // room for a draw's client-array vertices (its first ones); only grows
  std::vector<uint32_t> fetched_elements;     // a draw's array elements, for a shader reading them directly
  std::vector<uint8_t> copied_pixels;         // glCopyTex(Sub)Image's colour rectangle; only grows
  TransformedVertices transformed;  // vertex-stage output of the current draw
  IndexRuns index_runs;  // a large draw's runs (draw.cpp's draw_in_runs)
  // The current draw's vertex transform (draw.cpp's build_transform fills it): kept from draw to
  // draw, as constructing one and copying the lighting into it took a tenth of a one-triangle draw.
  raster::Transform draw_transform;
  // The state that draw_transform and draw_state's texture units, viewport, culling and per-vertex
  // point sizes were worked out from for a fixed-function draw (draw.cpp's prepare_fixed_function);
  // a draw that changes one of them resets it.
  StateKey fixed_function_prepared;
  // Materials set between glBegin and glEnd: vertices from `first` on are lit with them
  // (empty when the material did not change inside the primitive); the first is the one in
  // effect at glBegin.
  struct MaterialChange {
    size_t first;
    raster::Material front, back;
  };
  std::vector<MaterialChange> immediate_materials;

  // Current vertex attributes
  float current_color[4] = {1, 1, 1, 1};
  float current_normal[3] = {0, 0, 1};
  bool current_edge_flag = true;
  ColorIndexState color_index;  // current index, clear index, index mask (RGBA visuals ignore them)
  GLuint active_texture = 0, client_active_texture = 0;

  // Transform
  GLenum matrix_mode = GL_MODELVIEW;
  MatrixStack modelview, projection;
  std::array<MatrixStack, raster::kMaxTextureUnits> texture_matrix;
  raster::Viewport viewport;
  bool normalize = false, rescale_normal = false;

  // Rasterization & fragment state lives in its raster form; GL enums are translated on set.
  raster::DrawState draw_state;
  bool enable_cull = false;
  GLenum cull_face_mode = GL_BACK, front_face = GL_CCW;
  GLenum polygon_mode_front = GL_FILL, polygon_mode_back = GL_FILL;
  GLenum shade_model = GL_SMOOTH;
  bool line_stipple = false, polygon_stipple = false;
  raster::Lighting lighting;
  GLenum color_material_face = GL_FRONT_AND_BACK, color_material_mode = GL_AMBIENT_AND_DIFFUSE;
  VertexExtrasState extras;  // fog, clip planes, texgen, secondary colour (state/api_fog.cpp...)
  MultisampleState& multisample = draw_state.multisample;
  // Capabilities GL 1.1 accepts whose rendering Pineda does not do yet (fog, stipple,
  // smoothing, clip planes, texgen, evaluators): the enable bit is kept for glIsEnabled.
  std::unordered_map<GLenum, bool> unrendered_caps;
  EvaluatorState eval;  // glMap/glMapGrid maps, grids and enables

  // Raw GL values for glGet
  GLenum depth_func = GL_LESS, alpha_func = GL_ALWAYS;
  GLenum stencil_func = GL_ALWAYS, stencil_fail = GL_KEEP, stencil_zfail = GL_KEEP, stencil_zpass = GL_KEEP;
  GLenum logic_op = GL_COPY;
  GLuint stencil_value_mask = ~0u, stencil_write_mask = ~0u;
  StencilBackValues stencil_back_values;  // GL 2.0: the back face's (the front's are above)

  // Clear values
  float clear_color[4] = {0, 0, 0, 0};
  double clear_depth = 1.0;
  GLint clear_stencil = 0;

  // Hints
  GLenum hint_perspective = GL_DONT_CARE, hint_point = GL_DONT_CARE, hint_line = GL_DONT_CARE,
         hint_polygon = GL_DONT_CARE, hint_fog = GL_DONT_CARE;
  GLenum hint_generate_mipmap = GL_DONT_CARE, hint_texture_compression = GL_DONT_CARE;  // GL 1.3, 1.4

  // Client arrays and pixel storage
  ClientArray vertex_array, color_array, normal_array;
  ClientArray edge_flag_array = initial_array(1, GL_UNSIGNED_BYTE);  // GLboolean flags
  ClientArray fog_coord_array = initial_array(1), secondary_color_array = initial_array(3);
  ClientArray index_array = initial_array(1);
  ClientArray point_size_array = initial_array(1);  // OpenGL ES 1.1 (OES_point_size_array)
  PixelStore pack, unpack;

  // Textures
  // Texture image units: the bindings of all, the fixed-function state (enables, environment,
  // texture coordinates) of the first raster::kMaxTextureUnits only.
  std::array<TextureUnitState, raster::kMaxTextureImageUnits> texture_units;
  TextureNamespace& textures;  // the share group's
  SamplerNames& samplers;  // the share group's

  GLenum draw_buffer = GL_BACK, read_buffer = GL_BACK;
  ExtraDrawBuffers extra_draw_buffers{};  // DRAW_BUFFER1.. (glDrawBuffers), GL_NONE by default

  // Raster position and pixel rectangles
  RasterPosition raster_pos;
  PixelMode pixel_mode;
  PixelMaps pixel_maps;

  // Buffer objects and queries
  BufferState buffers{share_group_->buffers};
  QueryState queries;
  RenderModeState render_mode;  // glRenderMode: selection and feedback
  AccumState accum;
  ProgramState programs{share_group_->programs};  // GL 2.0 shader and program objects, generic attributes (state/programs/)

  FramebufferState framebuffers{share_group_->renderbuffers};  // framebuffer and renderbuffer objects (state/framebuffers/)
  // Vertex array objects (GL_ARB_vertex_array_object, state/vertex_arrays/): the arrays above
  // are the bound object's; the others keep theirs there.
  VertexArrayObjects vertex_array_objects;

  // Display lists
  DisplayLists& lists;  // the share group's
  ListCompilation compilation;
  GLuint list_base = 0;
  int list_depth = 0;  // nesting of glCallList

  // glPushAttrib / glPushClientAttrib
  std::vector<AttribFrame> attrib_stack;
  std::vector<ClientAttribFrame> client_attrib_stack;
  std::string version_string;  // storage for glGetString(GL_VERSION)

 private:
  // Points the renderer at the draw buffers; unless `always`, only when they changed.
  void bind_framebuffer(bool always = true);
  // Points the renderer at one colour buffer of the window, written as draw buffer `draw_buffer`.
  void use_color_buffer(const raster::ColorBuffer& color, int draw_buffer = 0);

  ContextAttribs attribs_;
  GLenum error_ = GL_NO_ERROR;
  uint64_t errors_recorded_ = 0;
  uint64_t state_changes_ = 1;  // (StateKey)
  // The storage that the renderer's framebuffer points into (Drawable::kept_storage), alive
  // until it no longer does (another context may respecify or delete the renderbuffers and
  // textures meanwhile). Before renderer_: a scene still running when the context goes writes it.
  std::vector<std::shared_ptr<const void>> renderer_storage_;
  std::unique_ptr<raster::Renderer> renderer_;
  Drawable* draw_ = nullptr;
  Drawable* read_ = nullptr;
  Drawable* fbo_draw_ = nullptr;
  Drawable* fbo_read_ = nullptr;
  int draw_pass_output_ = 0;
  bool ever_bound_ = false;
};

}  // namespace pineda
