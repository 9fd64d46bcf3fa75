#include "state/lists/display_list.h"

namespace pineda {

GLuint DisplayLists::generate(GLsizei range) {
  if (range <= 0) return 0;
  GLuint first = 1;
  // Lists are few; scan the gaps between existing names for `range` free ones.
  for (const auto& [name, list] : lists_) {
    if (name >= first && name - first >= GLuint(range)) break;
    if (name >= first) first = name + 1;
  }
  if (first == 0 || GLuint(-1) - first < GLuint(range)) return 0;
  for (GLsizei i = 0; i < range; ++i) lists_[first + i] = std::make_shared<const DisplayList>();
  return first;
}

std::shared_ptr<const DisplayList> DisplayLists::find(GLuint name) const {
  auto it = lists_.find(name);
  return it == lists_.end() ? nullptr : it->second;
}

void DisplayLists::remove(GLuint first, GLsizei range) {
  if (range <= 0) return;
  const GLuint last = GLuint(-1) - first < GLuint(range - 1) ? GLuint(-1) : first + GLuint(range - 1);
  lists_.erase(lists_.lower_bound(first), lists_.upper_bound(last));
}

}  // namespace pineda
