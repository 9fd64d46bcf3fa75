#include "shader/var_type.h"

#include <sstream>

#include "shader/type_name.h"

namespace pineda::shader {

std::string type_name(const VarType& t) {
  std::ostringstream s;
  if (t.is_struct()) {
    s << "struct {";
    for (const auto& m : t.members) s << " " << type_name(m.second) << " " << m.first << ";";
    s << " }";
  } else {
    switch (t.base) {
      case BaseType::Float:
        if (t.cols > 1) {
          s << "mat" << t.cols;
          if (t.cols != t.rows) s << "x" << t.rows;
        } else if (t.rows > 1) {
          s << "vec" << t.rows;
        } else {
          s << "float";
        }
        break;
      case BaseType::Int: s << (t.rows > 1 ? "ivec" + std::to_string(t.rows) : "int"); break;
      case BaseType::Bool: s << (t.rows > 1 ? "bvec" + std::to_string(t.rows) : "bool"); break;
      case BaseType::Sampler1D: s << "sampler1D"; break;
      case BaseType::Sampler2D: s << "sampler2D"; break;
      case BaseType::Sampler3D: s << "sampler3D"; break;
      case BaseType::SamplerCube: s << "samplerCube"; break;
      case BaseType::Sampler1DShadow: s << "sampler1DShadow"; break;
      case BaseType::Sampler2DShadow: s << "sampler2DShadow"; break;
      case BaseType::Sampler2DRect: s << "sampler2DRect"; break;
      case BaseType::Sampler2DRectShadow: s << "sampler2DRectShadow"; break;
    }
  }
  if (t.array) s << "[" << t.array << "]";
  return s.str();
}

std::string type_name(const Type& type) {
  VarType t = VarType::scalar(type.base);
  t.cols = type.columns;
  t.rows = type.rows;
  return type_name(t);
}

}  // namespace pineda::shader
