#include "shader/interface.h"

namespace pineda::shader {

const UniformVar* Interface::uniform(const std::string& name, const VarType& type, bool builtin,
                                     std::string& error) {
  for (const UniformVar& u : uniforms)
    if (u.name == name) {
      if (!(u.type == type)) {
        error = "error: uniform `" + name + "' declared as type `" + type_name(u.type) +
                "' and as type `" + type_name(type) + "'\n";
        return nullptr;
      }
      return &u;
    }
  uniforms.push_back(UniformVar{name, type, uniform_floats, builtin, {}});
  uniform_floats += type.size();
  return &uniforms.back();
}

VaryingVar* Interface::find_varying(const std::string& name) {
  for (VaryingVar& v : varyings)
    if (v.name == name) return &v;
  return nullptr;
}

VaryingVar& Interface::add_varying(const std::string& name, const VarType& type) {
  varyings.push_back(VaryingVar{name, type, varying_floats, -1});
  varying_floats += type.size();
  return varyings.back();
}

}  // namespace pineda::shader
