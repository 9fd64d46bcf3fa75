// The uniforms a linked program shows the application: built-ins left out, one location per
// array element, and name lookups as glGetUniformLocation takes them ("a", "a[2]", "s.m").
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "shader/program.h"

namespace pineda {

struct UniformLocation {
  int uniform = 0;  // index into UniformTable::active
  int element = 0;
};

struct UniformTable {
  std::vector<shader::Uniform> active;       // as glGetActiveUniform reports them, in order
  std::vector<UniformLocation> locations;    // indexed by location
  std::vector<int> first_location;           // of each active uniform's element 0

  static UniformTable build(const std::vector<shader::Uniform>& uniforms);
  // -1 when `name` names no active uniform element.
  int location(std::string_view name) const;
  // The uniform's name without a trailing "[0]".
  static std::string_view base_name(const shader::Uniform& u);
};

}  // namespace pineda
