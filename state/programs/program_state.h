// The GL 2.0 programmable-pipeline state of a context: shader and program objects, the
// program in use, and the generic vertex attributes (current values and arrays).
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <array>
#include <memory>
#include <vector>

#include "raster/draw_state.h"
#include "raster/shader_draw.h"
#include "shader/program.h"
#include "state/buffers/buffer_object.h"
#include "state/programs/program_objects.h"
#include "state/programs/shader_draw_pool.h"
#include "state/programs/vertex_run_scratch.h"
#include "state/state_key.h"

namespace pineda {

constexpr int kMaxVertexAttribs = shader::kMaxVertexAttribs;

struct GenericArray {
  bool enabled = false;
  bool normalized = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0;
  const void* pointer = nullptr;
  std::shared_ptr<BufferObject> buffer;
  bool active() const { return enabled && (pointer || buffer); }
};

struct ProgramState {
  explicit ProgramState(ShaderProgramNames& shared_objects) : objects(shared_objects) {}
  ProgramState(const ProgramState&) = delete;
  ProgramState& operator=(const ProgramState&) = delete;
  ~ProgramState() { use(0, nullptr); }  // a destroyed context stops using its program

  // Makes `program` (a linked program's name, or 0) current, releasing the previous one.
  void use(GLuint program, std::shared_ptr<LinkedProgram> exec);

  ShaderProgramNames& objects;  // the share group's
  GLuint current = 0;                            // glUseProgram's name (0: fixed function)
  std::shared_ptr<LinkedProgram> current_exec;   // what draws run; kept when a relink fails
  bool point_size_from_shader = false;           // GL_VERTEX_PROGRAM_POINT_SIZE
  bool two_side = false;                         // GL_VERTEX_PROGRAM_TWO_SIDE
  GLenum derivative_hint = GL_DONT_CARE;         // GL_FRAGMENT_SHADER_DERIVATIVE_HINT (accepted)

  std::array<std::array<float, 4>, kMaxVertexAttribs> current_attrib = [] {
    std::array<std::array<float, 4>, kMaxVertexAttribs> a{};
    for (auto& v : a) v = {0, 0, 0, 1};
    return a;
  }();
  std::array<GenericArray, kMaxVertexAttribs> arrays;

  // Generic attribute values of the vertices specified between glBegin and glEnd while a
  // program is in use: kMaxVertexAttribs vec4 per vertex (VertexInput::generic indexes them).
  std::vector<float> immediate_generic;
  // The vertex shader's varyings of the current draw (scratch).
  std::vector<float> draw_varyings;
  // The last draw's program, uniform values and facing: a draw that changed none of them shares
  // it (program_draw.cpp), and then its record (raster::Scene::repeat_of_current_draw).
  std::shared_ptr<const raster::ShaderDraw> last_shader_draw;
  ShaderDrawPool shader_draws;  // where the draws' ShaderDraws come from
  std::vector<float> draw_uniforms;  // (scratch)
  // The last draw's whole state (last_shader_draw, the textures its samplers read, ...) and the
  // state it was worked out from: a draw of the same state takes it as it is (program_draw.cpp).
  raster::DrawState draw_state;
  StateKey draw_state_prepared;
  VertexRunScratch vertex_run;  // (scratch)

  // A program with a vertex shader is in use: draws run it.
  const LinkedProgram* active() const { return current_exec.get(); }
};

}  // namespace pineda
