// Display lists: recorded calls, replayed by glCallList.
#pragma once
#include <GL/gl.h>

#include <functional>
#include <map>
#include <memory>
#include <vector>

namespace pineda {

class Context;

using ListCommand = std::function<void(Context&)>;

struct DisplayList {
  std::vector<ListCommand> commands;
};

class DisplayLists {
 public:
  // Reserves `range` consecutive unused names as empty lists; returns the first, or 0.
  GLuint generate(GLsizei range);
  bool exists(GLuint name) const { return lists_.count(name) != 0; }
  std::shared_ptr<const DisplayList> find(GLuint name) const;
  void define(GLuint name, std::shared_ptr<const DisplayList> list) { lists_[name] = std::move(list); }
  void remove(GLuint first, GLsizei range);

 private:
  std::map<GLuint, std::shared_ptr<const DisplayList>> lists_;
};

// The list under construction between glNewList and glEndList.
struct ListCompilation {
  GLuint name = 0;  // 0: not compiling
  GLenum mode = GL_COMPILE;
  std::shared_ptr<DisplayList> list;
};

constexpr int kMaxListNesting = 64;

}  // namespace pineda
