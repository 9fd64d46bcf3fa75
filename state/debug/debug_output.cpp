#include "state/debug/debug_output.h"

#include <algorithm>
#include <cstdio>

namespace pineda {
namespace {

bool matches(GLenum rule_value, GLenum value) { return rule_value == GL_DONT_CARE || rule_value == value; }

// Whether every message `later` matches is also matched by `earlier`'s match set, so that
// `later` makes `earlier` irrelevant (keeps the rule list from growing without bound).
bool covers(const auto& later, const auto& earlier) {
  auto wider = [](GLenum a, GLenum b) { return a == GL_DONT_CARE || a == b; };
  if (!wider(later.source, earlier.source) || !wider(later.type, earlier.type) ||
      !wider(later.severity, earlier.severity))
    return false;
  if (later.ids.empty()) return true;
  if (earlier.ids.empty()) return false;
  return std::all_of(earlier.ids.begin(), earlier.ids.end(), [&](GLuint id) {
    return std::find(later.ids.begin(), later.ids.end(), id) != later.ids.end();
  });
}

}  // namespace

const char* error_name(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    default: return "GL error";
  }
}

std::string hex_enum(GLenum value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04x", unsigned(value));
  return text;
}

DebugOutput::DebugOutput(bool debug_context, bool print_errors)
    : enabled(debug_context), print_errors_(print_errors) {
  groups_.push_back(Group{GL_DEBUG_SOURCE_APPLICATION, 0, "", {}});
}

void DebugOutput::report_error(const char* call, GLenum error, std::string_view why) {
  std::string text = call && *call ? std::string(call) + ": " : std::string();
  text += error_name(error);
  if (!why.empty()) {
    text += ": ";
    text += why;
  }
  if (print_errors_) std::fprintf(stderr, "pineda: %s\n", text.c_str());
  if (enabled) emit(GL_DEBUG_SOURCE_API, GL_DEBUG_TYPE_ERROR, error, GL_DEBUG_SEVERITY_HIGH, text);
}

bool DebugOutput::is_enabled(GLenum source, GLenum type, GLuint id, GLenum severity) const {
  bool on = severity != GL_DEBUG_SEVERITY_LOW;  // KHR_debug: LOW starts disabled
  for (const Rule& r : groups_.back().rules) {
    if (!matches(r.source, source) || !matches(r.type, type) || !matches(r.severity, severity)) continue;
    if (!r.ids.empty() && std::find(r.ids.begin(), r.ids.end(), id) == r.ids.end()) continue;
    on = r.enable;
  }
  return on;
}

void DebugOutput::emit(GLenum source, GLenum type, GLuint id, GLenum severity, std::string_view text) {
  if (!enabled || !is_enabled(source, type, id, severity)) return;
  // Messages longer than the limit are cut to it, as a callback or the log may assume.
  std::string message(text.substr(0, kMaxMessageLength - 1));
  if (callback) {
    callback(source, type, id, severity, GLsizei(message.size()), message.c_str(), user_param);
    return;
  }
  if (int(log_.size()) < kMaxLoggedMessages) log_.push_back({source, type, id, severity, std::move(message)});
}

void DebugOutput::control(GLenum source, GLenum type, GLenum severity, std::vector<GLuint> ids, bool enable) {
  std::vector<Rule>& rules = groups_.back().rules;
  Rule rule{source, type, severity, std::move(ids), enable};
  std::erase_if(rules, [&](const Rule& earlier) { return covers(rule, earlier); });
  rules.push_back(std::move(rule));
}

void DebugOutput::push_group(GLenum source, GLuint id, std::string message) {
  emit(source, GL_DEBUG_TYPE_PUSH_GROUP, id, GL_DEBUG_SEVERITY_NOTIFICATION, message);
  std::vector<Rule> inherited = groups_.back().rules;
  groups_.push_back(Group{source, id, std::move(message), std::move(inherited)});
}

void DebugOutput::pop_group() {
  Group popped = std::move(groups_.back());
  groups_.pop_back();
  emit(popped.source, GL_DEBUG_TYPE_POP_GROUP, popped.id, GL_DEBUG_SEVERITY_NOTIFICATION, popped.message);
}

void DebugOutput::set_label(GLenum identifier, GLuint name, std::string label) {
  if (label.empty())
    labels_.erase({identifier, name});
  else
    labels_[{identifier, name}] = std::move(label);
}

const std::string* DebugOutput::label(GLenum identifier, GLuint name) const {
  auto it = labels_.find({identifier, name});
  return it == labels_.end() ? nullptr : &it->second;
}

}  // namespace pineda
