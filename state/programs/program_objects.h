// Shader and program objects (GL 2.0 section 2.15): one name space for both, deferred
// deletion, and the linked executable a program hands to draws.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "shader/program.h"
#include "state/programs/uniform_table.h"

namespace pineda {

struct ShaderObject {
  GLenum type = GL_VERTEX_SHADER;
  std::vector<std::string> sources;  // glShaderSource's strings, in order
  bool has_source = false;
  std::shared_ptr<const shader::CompiledShader> compiled;  // the last successful compile
  bool compile_status = false;
  std::string info_log;
  bool delete_pending = false;
  int attachments = 0;  // programs this shader is attached to
};

// What a successful link produces; immutable but for the uniform values, which glUniform
// changes while the program is in use (a draw copies them).
struct LinkedProgram {
  std::shared_ptr<const shader::Program> program;
  UniformTable uniforms;        // the active uniforms the application sees, with locations
  std::vector<float> values;    // shader::Program::uniform_floats() values
  std::vector<int> attributes;  // indices into program->attributes() (built-ins included)
  bool vertex_shader = false, fragment_shader = false;  // which stages the program replaces
  bool generic_attributes_only = false;  // the vertex shader reads no built-in attribute (gl_Vertex, ...)
  std::string sampler_conflict;  // sampler_unit_conflict(*this): a draw is INVALID_OPERATION unless empty
};

struct ProgramObject {
  std::vector<GLuint> attached;             // shader names, in attach order
  std::map<std::string, GLuint> bindings;   // glBindAttribLocation, applied at the next link
  bool link_status = false, validate_status = false;
  std::string info_log;
  bool delete_pending = false;
  int contexts_using = 0;  // contexts of the share group with this program current
  std::shared_ptr<LinkedProgram> executable;  // null until a link succeeds, and after one fails
};

// Shader and program objects share one name space (GL 2.0 2.15.1), held by the share group
// (GL 2.1 Appendix D: shader and program objects are shared).
class ShaderProgramNames {
 public:
  GLuint create_shader(GLenum type);
  GLuint create_program();
  ShaderObject* shader(GLuint name);
  ProgramObject* program(GLuint name);
  bool exists(GLuint name) const { return name != 0 && (shaders_.count(name) || programs_.count(name)); }
  void remove_shader(GLuint name) { shaders_.erase(name); }
  void remove_program(GLuint name) { programs_.erase(name); }
  // Frees a program flagged for deletion once no context uses it, and the shaders only it
  // kept alive (GL 2.0 2.15.3).
  void destroy_program_if_unused(GLuint name);

 private:
  GLuint next_name();
  std::map<GLuint, std::unique_ptr<ShaderObject>> shaders_;
  std::map<GLuint, std::unique_ptr<ProgramObject>> programs_;
  GLuint next_ = 1;
};

}  // namespace pineda
