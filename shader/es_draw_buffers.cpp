#include "shader/es_draw_buffers.h"

#include <cctype>
#include <string_view>

namespace pineda::shader {
namespace {

constexpr std::string_view kName = "GL_EXT_draw_buffers";

enum class Behaviour { None, Enable, Disable };

void skip_blanks(std::string_view line, size_t& at) {
  while (at < line.size() && (line[at] == ' ' || line[at] == '\t')) ++at;
}

std::string_view word(std::string_view line, size_t& at) {
  const size_t start = at;
  while (at < line.size() && (std::isalnum(static_cast<unsigned char>(line[at])) || line[at] == '_')) ++at;
  return line.substr(start, at - start);
}

// What `line` says of the extension, if it is one of its #extension directives with a
// behaviour GLSL ES 1.00 3.4 defines (anything else is left for glslang to judge).
Behaviour directive(std::string_view line) {
  size_t at = 0;
  skip_blanks(line, at);
  if (at >= line.size() || line[at] != '#') return Behaviour::None;
  ++at;
  skip_blanks(line, at);
  if (word(line, at) != "extension") return Behaviour::None;
  skip_blanks(line, at);
  if (word(line, at) != kName) return Behaviour::None;
  skip_blanks(line, at);
  if (at >= line.size() || line[at] != ':') return Behaviour::None;
  ++at;
  skip_blanks(line, at);
  const std::string_view behaviour = word(line, at);
  skip_blanks(line, at);
  const std::string_view rest = line.substr(at);
  if (!rest.empty() && rest != "\r" && !rest.starts_with("//")) return Behaviour::None;
  if (behaviour == "enable" || behaviour == "require" || behaviour == "warn") return Behaviour::Enable;
  if (behaviour == "disable") return Behaviour::Disable;
  return Behaviour::None;
}

}  // namespace

bool take_draw_buffers_directives(std::vector<std::string>& sources) {
  bool enabled = false;
  for (std::string& source : sources) {
    size_t start = 0;
    while (start <= source.size()) {
      size_t end = source.find('\n', start);
      if (end == std::string::npos) end = source.size();
      const Behaviour b = directive(std::string_view(source).substr(start, end - start));
      if (b != Behaviour::None) {
        enabled = b == Behaviour::Enable;
        for (size_t i = start; i < end; ++i)
          if (source[i] != '\r') source[i] = ' ';
      }
      start = end + 1;
    }
  }
  return enabled;
}

}  // namespace pineda::shader
