// What state/ and raster/ see of shader/: compile, link, reflect, and run a linked program
// over lanes. shader/ knows no GL enums and calls nothing above it; state/ maps its types
// and names to GL tokens, raster/ feeds it vertices and fragments.
//
// Every value is 32-bit float per lane: GLSL 1.10/1.20 and ES 1.00 allow ints to be carried
// as floats (integers need only 16 bits plus sign), bools are 0.0 or 1.0, samplers hold the
// texture unit. Matrices are column-major, one vec per column.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace pineda::shader {

constexpr int kLanes = 16;       // a 4x4 fragment block, or a batch of 16 vertices
using LaneMask = uint16_t;       // bit i: lane i is live
constexpr int kMaxBlocksPerRun = 4;  // fragment blocks one run_fragment_blocks shades together
constexpr int kMaxDrawBuffers = 8;  // GL_MAX_DRAW_BUFFERS, as Mesa
constexpr int kMaxVaryingFloats = 64;   // GL_MAX_VARYING_FLOATS (16 vec4)
constexpr int kMaxVertexAttribs = 16;

enum class Stage : uint8_t { Vertex, Fragment };
// Desktop: GLSL 1.10 (no #version) or 1.20 with the compatibility built-ins.
// Es100: GLSL ES 1.00 (#version 100, or no #version).
enum class Language : uint8_t { Desktop, Es100 };

enum class BaseType : uint8_t {
  Float, Int, Bool,
  Sampler1D, Sampler2D, Sampler3D, SamplerCube, Sampler1DShadow, Sampler2DShadow,
  Sampler2DRect, Sampler2DRectShadow  // ARB_texture_rectangle
};
struct Type {
  BaseType base = BaseType::Float;
  uint8_t columns = 1;  // 2..4 for matN / matNxM, 1 otherwise
  uint8_t rows = 1;     // vector size (1 for scalars and samplers)
  int components() const { return columns * rows; }
};

struct CompiledShader;  // immutable once compiled; defined inside shader/

struct CompileResult {
  std::shared_ptr<const CompiledShader> shader;  // null when compilation failed
  std::string info_log;                          // glslang's words (may be non-empty on success)
};
// `sources` are the glShaderSource strings, in order (concatenated, as GL specifies).
CompileResult compile(Stage stage, Language language, const std::vector<std::string>& sources);

// Built-in vertex inputs of desktop GLSL; gl_Vertex and generic attribute 0 are the same input.
enum class BuiltinAttribute : uint8_t {
  None, Vertex, Normal, Color, SecondaryColor, FogCoord, MultiTexCoord0 /* ...7 follow */
};

// An active vertex input. Generic inputs get `location` (glBindAttribLocation's choice, or
// the linker's); built-ins carry their kind and location -1.
struct Attribute {
  std::string name;
  Type type;
  int array_size = 1;
  int location = -1;
  BuiltinAttribute builtin = BuiltinAttribute::None;
  int input_slot = 0;  // index into VertexBatch::inputs (one vec4 slot per column / element)
};

// An active uniform. Arrays are reported once, named "a[0]" as GL requires for glGetActiveUniform,
// with `array_size` elements of `type`, element i at offset + i * stride floats. Built-in state
// uniforms (gl_ModelViewMatrix, gl_LightSource[0].diffuse, ...) are listed with their GLSL
// names and `builtin` set: state/ fills them from GL state at each draw and never reports them.
struct Uniform {
  std::string name;
  Type type;
  int array_size = 1;
  int offset = 0;  // in floats, into the program's UniformStore
  int stride = 0;  // floats between array elements
  bool builtin = false;
  // Added: a GLSL 1.20 initializer (`uniform float k = 2.0;`), array_size * stride floats in
  // store order; empty when the uniform has none (it starts at zero).
  std::vector<float> initial;
};

// Where each fragment input comes from. `offset` indexes the interpolated varying floats;
// a front/back pair (gl_Color from gl_FrontColor/gl_BackColor) also has `back_offset`, which
// raster/ uses instead for back-facing polygons when two-sided colour applies.
struct Varying {
  std::string name;  // user name or built-in (gl_TexCoord[1], gl_Color, ...)
  int offset = 0;
  int components = 4;
  int back_offset = -1;
};

// Vertex outputs: floats 0..3 gl_Position, 4 gl_PointSize, 5..8 gl_ClipVertex (the user
// clip planes' eye-space point; gl_Position when the shader does not write it, as Mesa),
// then `varying_floats` floats that raster/ interpolates (perspective-correct) and hands to
// the fragment shader in the same order. Outputs the vertex shader does not write hold 0
// (gl_Position (0,0,0,0)).
constexpr int kOutPosition = 0;
constexpr int kOutPointSize = 4;
constexpr int kOutClipVertex = 5;
constexpr int kOutFirstVarying = 9;

struct VertexBatch {
  int count = 0;                 // live vertices, 1..kLanes (lanes past count hold garbage)
  const float* inputs = nullptr;  // [input slot][4 components][kLanes]
  float* outputs = nullptr;       // [kOutFirstVarying + varying_floats][kLanes]
  // Program::vertex_uniform_values() of this draw's uniforms, or null (computed per run).
  const float* uniform_values = nullptr;
  // The caller runs under the shader modes (ir::FlushDenormals: round to nearest, FTZ and DAZ,
  // exceptions masked): a run leaves the modes alone (it reads the first batch's).
  bool denormals_flushed = false;
};

// Texture lookups go back to raster/ through this interface, 16 lanes at a time.
enum class SamplerKind : uint8_t { Tex1D, Tex2D, Tex3D, Cube, Shadow1D, Shadow2D, Rect, ShadowRect };
enum class LodMode : uint8_t {
  Implicit,  // from the coordinates' differences across each 2x2 quad of lanes (fragments)
  Bias,      // implicit plus lod[] (the bias argument)
  Explicit   // lod[] is the level of detail (texture*Lod, and every vertex-shader lookup)
};
// The texture unit a sampler's lane value names (out of range: unit 0).
inline int sampler_unit(float unit) { return unit >= 0.0f && unit < 256.0f ? static_cast<int>(unit) : 0; }

class TextureAccess {
 public:
  virtual ~TextureAccess() = default;
  // coords[c][lane]: s, t, r, q as the lookup needs them (projection already divided out,
  // the shadow reference in r for Shadow*); out[c][lane]: RGBA after the texture's base format.
  virtual void sample(int unit, SamplerKind kind, const float (*coords)[kLanes], LodMode mode,
                      const float* lod, LaneMask live, float (*out)[kLanes]) const = 0;
  // The same as sample(unit, Tex2D, {s, t}, Implicit, nullptr, live, out) by a shorter route
  // where the unit's texture has one (out[c] may be s or t), except that the quads without a
  // live lane may read any texel (all 16 lanes are written); false, with nothing written, where
  // it has none.
  virtual bool sample_2d_block(int unit, const float* s, const float* t, LaneMask live, float* const out[4]) const {
    (void)unit, (void)s, (void)t, (void)live, (void)out;
    return false;
  }
  // sample_2d_block for `count` lookups of one unit in order (lookup k reads s[k] and t[k] and
  // writes out[k]; no lookup reads what an earlier one writes); false, with nothing written,
  // where the unit has no such route (which depends on the unit alone).
  virtual bool sample_2d_blocks(int unit, int count, const float* const* s, const float* const* t, LaneMask live,
                                float* const (*out)[4]) const {
    if (count < 1 || !sample_2d_block(unit, s[0], t[0], live, out[0])) return false;
    for (int k = 1; k < count; ++k) sample_2d_block(unit, s[k], t[k], live, out[k]);
    return true;
  }
};

// One block of 16 fragments (value-initialize it, FragmentBlock{}, for zeros: the arrays have
// no initializers, so that raster/ fills only what a program reads): four 2x2 quads, lanes
// 4q..4q+3 forming quad q, lane 4q + i its pixel (x_q + (i & 1), y_q + (i >> 1)), so that
// derivatives (dFdx: lane ^ 1, dFdy: lane ^ 2) and implicit LOD come from real neighbours. Which
// quads make a block is the caller's choice: raster/ takes up to four quads of one pixel-row
// pair of a primitive, adjacent or not (a 4x4 square would be quads (x0, y0), (x0 + 2, y0),
// (x0, y0 + 2), (x0 + 2, y0 + 2)).
struct FragmentBlock {
  LaneMask live = 0;                  // in: covered; out: covered and not discarded
  // Lanes to run. 0: every lane of a quad with a live pixel. A caller that fills the lanes of
  // quads without a live pixel with a copy of a live quad (raster/ does) runs all 16, so that
  // straight-line code never blends under a partial mask; texture lookups still read only the
  // quads with a live pixel, and the other lanes' results are unspecified.
  LaneMask run = 0;
  // Program::fragment_uniform_values() of this draw's uniforms, or null (computed per block).
  const float* uniform_values = nullptr;
  const float* varyings = nullptr;    // [varying float][kLanes], already perspective-divided
  bool denormals_flushed = false;     // as VertexBatch's (a run reads the first block's)
  LaneMask front_facing = 0;
  // Each row of lanes on a 64-byte line: the executors read and write whole rows, and a row
  // across two lines made every colour store two (glsl_lit spent a tenth of its time there).
  alignas(64) float frag_coord[4][kLanes];  // x+0.5, y+0.5, window z, 1/w
  float point_coord[2][kLanes];
  // out: gl_FragData[i] < draw_buffers_written(), or gl_FragColor in color[0] alone (broadcasts_color():
  // the caller reads it for every draw buffer, so one bound buffer costs one store).
  float color[kMaxDrawBuffers][4][kLanes];
  float depth[kLanes];                      // out, when writes_depth()
};

// A linked program: immutable, safe to run from several threads at once.
class Program {
 public:
  virtual ~Program() = default;
  virtual const std::vector<Attribute>& attributes() const = 0;
  virtual const std::vector<Uniform>& uniforms() const = 0;
  virtual const std::vector<Varying>& varyings() const = 0;  // fragment inputs
  virtual int input_slots() const = 0;       // VertexBatch::inputs size, in vec4 slots
  virtual int varying_floats() const = 0;
  virtual int uniform_floats() const = 0;    // UniformStore size
  virtual bool writes_point_size() const = 0;
  virtual bool writes_depth() const = 0;
  virtual bool uses_discard() const = 0;
  virtual int draw_buffers_written() const = 0;  // 1 for gl_FragColor, else highest gl_FragData + 1
  virtual bool broadcasts_color() const = 0;     // writes gl_FragColor: color[0] is every draw buffer's
  virtual bool reads(const char* builtin) const = 0;  // "gl_FragCoord", "gl_FrontFacing", "gl_PointCoord"
  // Bit c set: the optimized fragment stage reads gl_FragCoord's component c (the caller fills
  // FragmentBlock::frag_coord[c] only for those).
  virtual unsigned frag_coord_components() const = 0;
  virtual bool reads_point_coord() const = 0;         // reads("gl_PointCoord"), without the lookup

  // `uniforms` has uniform_floats() values; `textures` may be null when no sampler is used.
  virtual void run_vertices(const float* uniforms, const TextureAccess* textures,
                            VertexBatch& batch) const = 0;
  // The same for `count` (1 to 4) batches at once, as run_fragment_blocks does for blocks.
  virtual void run_vertex_batches(const float* uniforms, const TextureAccess* textures, VertexBatch* batches,
                                  int count) const = 0;
  virtual void run_fragments(const float* uniforms, const TextureAccess* textures,
                             FragmentBlock& block) const = 0;
  // The same for `count` (1 to 4) blocks of one draw at once: each comes out as run alone,
  // and each instruction's dispatch serves them all.
  virtual void run_fragment_blocks(const float* uniforms, const TextureAccess* textures, FragmentBlock* blocks,
                                   int count) const = 0;
  // What the fragment shader computes from uniforms alone (shader/hoist.h), for
  // FragmentBlock::uniform_values: computed once per draw instead of once per block. Into `out`
  // (resized; its room kept from draw to draw where the caller keeps it), empty when none.
  virtual void fragment_uniform_values(const float* uniforms, std::vector<float>& out) const = 0;
  // The same of the vertex shader, for VertexBatch::uniform_values.
  virtual void vertex_uniform_values(const float* uniforms, std::vector<float>& out) const = 0;
};

struct AttributeBinding {
  std::string name;
  int location;
};

struct LinkResult {
  std::shared_ptr<const Program> program;  // null when linking failed
  std::string info_log;
};
// Links one vertex and one fragment shader (either may be null: the fixed-function stage
// replaces it; state/ handles that case). `bindings` are glBindAttribLocation's, applied
// at this link. Initial uniform values are zero.
LinkResult link(const CompiledShader* vertex, const CompiledShader* fragment,
                const std::vector<AttributeBinding>& bindings);
// The same with any number of shaders per stage (desktop GLSL: glslang links the compilation
// units of a stage into one, one of them defining main()); an empty list is a missing stage.
LinkResult link(const std::vector<const CompiledShader*>& vertex, const std::vector<const CompiledShader*>& fragment,
                const std::vector<AttributeBinding>& bindings);

// The IR of a program as text, for PINEDA_DUMP_IR=1 and tests.
std::string dump_ir(const Program& program);

}  // namespace pineda::shader
