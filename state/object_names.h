// A GL name space for objects that are created at their first bind (buffers, queries):
// generated names stay reserved until then.
#pragma once
#include <GL/gl.h>

#include <map>
#include <memory>
#include <set>

namespace pineda {

template <typename T>
class ObjectNames {
 public:
  void generate(GLsizei n, GLuint* names) {
    for (GLsizei i = 0; i < n; ++i) {
      while (used(next_)) ++next_;
      reserved_.insert(next_);
      names[i] = next_++;
    }
  }
  // The object named `name` (not 0), created when missing.
  const std::shared_ptr<T>& get_or_create(GLuint name) {
    std::shared_ptr<T>& object = objects_[name];
    if (!object) object = std::make_shared<T>(name);
    reserved_.erase(name);
    return object;
  }
  std::shared_ptr<T> find(GLuint name) const {
    auto it = objects_.find(name);
    return it == objects_.end() ? nullptr : it->second;
  }
  void remove(GLuint name) {
    objects_.erase(name);
    reserved_.erase(name);
  }
  bool exists(GLuint name) const { return objects_.count(name) != 0; }
  // Generated and not deleted since (created or not yet).
  bool generated(GLuint name) const { return name != 0 && (objects_.count(name) || reserved_.count(name)); }

 private:
  bool used(GLuint name) const { return name == 0 || objects_.count(name) || reserved_.count(name); }

  std::map<GLuint, std::shared_ptr<T>> objects_;
  std::set<GLuint> reserved_;
  GLuint next_ = 1;
};

}  // namespace pineda
