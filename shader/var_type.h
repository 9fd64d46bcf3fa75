// The type of a GLSL variable as shader/ lays it out: every scalar is one float, matrices
// are column-major, arrays and structs are flattened in order.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "shader/program.h"

namespace pineda::shader {

struct VarType {
  // Declared, so that clang does not ask whether the incomplete VarType of `members` is
  // default-constructible (libstdc++'s std::pair does).
  VarType() = default;
  BaseType base = BaseType::Float;
  int cols = 1;   // > 1 for matrices
  int rows = 1;   // vector size
  int array = 0;  // element count, 0 when not an array
  std::vector<std::pair<std::string, VarType>> members;  // a struct when non-empty

  bool is_struct() const { return !members.empty(); }
  bool is_matrix() const { return cols > 1 && array == 0 && !is_struct(); }
  int element_size() const {
    if (!is_struct()) return cols * rows;
    int n = 0;
    for (const auto& m : members) n += m.second.size();
    return n;
  }
  int size() const { return element_size() * (array ? array : 1); }
  VarType element() const {
    VarType t = *this;
    t.array = 0;
    return t;
  }
  bool operator==(const VarType& o) const {
    return base == o.base && cols == o.cols && rows == o.rows && array == o.array && members == o.members;
  }
  static VarType scalar(BaseType b) { VarType t; t.base = b; return t; }
  static VarType vec(int n) { VarType t; t.rows = n; return t; }
  static VarType mat(int c, int r) { VarType t; t.cols = c; t.rows = r; return t; }
};

std::string type_name(const VarType& t);

}  // namespace pineda::shader
