// What the stages of a program share and what the program reports: uniforms (one store for
// both stages), vertex inputs, varyings, and the flags of program.h. Built while lowering.
#pragma once
#include <map>
#include <set>
#include <string>
#include <vector>

#include "shader/program.h"
#include "shader/var_type.h"

namespace pineda::shader {

struct UniformVar {
  std::string name;
  VarType type;
  int offset = 0;
  bool builtin = false;
  std::vector<float> initial;  // a GLSL 1.20 initializer, flattened; empty when none
};

struct AttributeVar {
  std::string name;
  VarType type;
  int first_slot = 0;
  BuiltinAttribute builtin = BuiltinAttribute::None;
};

// A fragment input: a user varying, or a built-in (gl_Color, gl_SecondaryColor,
// gl_TexCoord, gl_FogFragCoord) with the front/back pair for the colours.
struct VaryingVar {
  std::string name;
  VarType type;
  int offset = 0;
  int back_offset = -1;
};

struct Interface {
  std::vector<UniformVar> uniforms;
  int uniform_floats = 0;
  std::vector<AttributeVar> attributes;
  int input_slots = 0;
  std::vector<VaryingVar> varyings;
  int varying_floats = 0;
  bool has_vertex_shader = false;
  bool has_fragment_shader = false;

  bool writes_point_size = false;
  bool writes_depth = false;
  bool uses_discard = false;
  int draw_buffers = 0;
  bool broadcasts_color = false;  // gl_FragColor
  std::set<std::string> reads;

  // The uniform named `name` (shared by both stages), created when new; null on a type clash.
  const UniformVar* uniform(const std::string& name, const VarType& type, bool builtin, std::string& error);
  VaryingVar* find_varying(const std::string& name);
  VaryingVar& add_varying(const std::string& name, const VarType& type);
};

}  // namespace pineda::shader
