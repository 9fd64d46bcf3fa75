// GL_KHR_debug's message stream: the enable, the control rules per debug group, the log,
// the application's callback, and object labels. Errors reach it from Context::record_error.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>
#include <deque>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pineda {

struct DebugMessage {
  GLenum source, type;
  GLuint id;
  GLenum severity;
  std::string text;
};

class DebugOutput {
 public:
  static constexpr int kMaxMessageLength = 1024;  // includes the terminating null
  static constexpr int kMaxLoggedMessages = 64;
  static constexpr int kMaxGroupDepth = 64;
  static constexpr int kMaxLabelLength = 256;

  // DEBUG_OUTPUT starts enabled in a debug context; `print_errors` (PINEDA_DEBUG=1) writes
  // every API error message to stderr whatever the application asked for.
  DebugOutput(bool debug_context, bool print_errors);

  bool enabled = false;       // GL_DEBUG_OUTPUT
  bool synchronous = false;   // GL_DEBUG_OUTPUT_SYNCHRONOUS (messages are always delivered at once)
  GLDEBUGPROC callback = nullptr;
  const void* user_param = nullptr;

  // Whether an error message would go anywhere: when false, building its text is wasted.
  bool reports_errors() const { return enabled || print_errors_; }
  // An API error of `call` ("glTexImage2D"), with the rule it broke when known.
  void report_error(const char* call, GLenum error, std::string_view why);
  // A message through the control rules to the callback or the log.
  void emit(GLenum source, GLenum type, GLuint id, GLenum severity, std::string_view text);

  // glDebugMessageControl, already validated: GL_DONT_CARE matches any value; `ids`
  // empty matches any id.
  void control(GLenum source, GLenum type, GLenum severity, std::vector<GLuint> ids, bool enable);
  bool is_enabled(GLenum source, GLenum type, GLuint id, GLenum severity) const;

  const std::deque<DebugMessage>& log() const { return log_; }
  void pop_logged() { log_.pop_front(); }

  int group_depth() const { return int(groups_.size()); }
  // Push and pop a debug group (depth already checked); each emits its message.
  void push_group(GLenum source, GLuint id, std::string message);
  void pop_group();

  // Object labels by (identifier, name), e.g. (GL_TEXTURE, 3). An empty label is no label.
  void set_label(GLenum identifier, GLuint name, std::string label);
  const std::string* label(GLenum identifier, GLuint name) const;
  void forget_label(GLenum identifier, GLuint name) { labels_.erase({identifier, name}); }
  void forget_labels(GLenum identifier, GLuint first, GLuint last) {
    labels_.erase(labels_.lower_bound({identifier, first}), labels_.upper_bound({identifier, last}));
  }

 private:
  struct Rule {
    GLenum source, type, severity;
    std::vector<GLuint> ids;
    bool enable;
  };
  struct Group {
    GLenum source;
    GLuint id;
    std::string message;
    std::vector<Rule> rules;
  };

  bool print_errors_ = false;
  std::vector<Group> groups_;  // groups_[0] is the default group
  std::deque<DebugMessage> log_;
  std::map<std::pair<GLenum, GLuint>, std::string> labels_;
};

// "GL_INVALID_ENUM" for an error code.
const char* error_name(GLenum error);
// "0x0de1": an enum value as messages show it.
std::string hex_enum(GLenum value);

}  // namespace pineda
