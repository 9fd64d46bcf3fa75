#include "state/programs/uniform_table.h"

#include <algorithm>
#include <charconv>

namespace pineda {

std::string_view UniformTable::base_name(const shader::Uniform& u) {
  std::string_view n = u.name;
  if (n.size() > 3 && n.substr(n.size() - 3) == "[0]") n.remove_suffix(3);
  return n;
}

UniformTable UniformTable::build(const std::vector<shader::Uniform>& uniforms) {
  UniformTable t;
  for (const shader::Uniform& u : uniforms) {
    if (u.builtin) continue;
    const int index = static_cast<int>(t.active.size());
    t.active.push_back(u);
    t.first_location.push_back(static_cast<int>(t.locations.size()));
    for (int e = 0; e < std::max(u.array_size, 1); ++e) t.locations.push_back({index, e});
  }
  return t;
}

int UniformTable::location(std::string_view name) const {
  int element = 0;
  bool subscripted = false;
  if (!name.empty() && name.back() == ']') {
    const size_t open = name.rfind('[');
    if (open == std::string_view::npos) return -1;
    const std::string_view digits = name.substr(open + 1, name.size() - open - 2);
    if (digits.empty() || digits.size() > 9) return -1;
    for (char c : digits)
      if (c < '0' || c > '9') return -1;
    std::from_chars(digits.data(), digits.data() + digits.size(), element);
    name = name.substr(0, open);
    subscripted = true;
  }
  for (size_t i = 0; i < active.size(); ++i) {
    const shader::Uniform& u = active[i];
    if (base_name(u) != name) continue;
    const bool is_array = u.name.size() > name.size();  // reported as "a[0]"
    if (subscripted && !is_array) return -1;
    if (element >= std::max(u.array_size, 1)) return -1;
    return first_location[i] + element;
  }
  return -1;
}

}  // namespace pineda
