#include "state/programs/sampler_units.h"

#include <algorithm>

#include "raster/texture.h"
#include "shader/type_name.h"

namespace pineda {

std::string sampler_unit_conflict(const LinkedProgram& exec) {
  const shader::Type* unit_type[raster::kMaxTextureImageUnits] = {};
  for (const shader::Uniform& u : exec.uniforms.active) {
    if (u.type.base < shader::BaseType::Sampler1D) continue;  // not a sampler
    for (int e = 0; e < std::max(u.array_size, 1); ++e) {
      const size_t at = static_cast<size_t>(u.offset + e * u.stride);
      if (at >= exec.values.size()) continue;
      const int unit = static_cast<int>(exec.values[at]);
      if (unit < 0 || unit >= raster::kMaxTextureImageUnits) continue;
      const shader::Type*& seen = unit_type[unit];
      if (seen && seen->base != u.type.base)
        return "Texture unit " + std::to_string(unit) + " is accessed both as " + shader::type_name(*seen) + " and " +
               shader::type_name(u.type);
      seen = &u.type;
    }
  }
  return {};
}

}  // namespace pineda
