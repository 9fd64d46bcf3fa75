// A compile error as glslang words its own: "ERROR: <string>:<line>: '<what>' : <why>", then
// its closing count (the front end's own checks end the info log as glslang would).
#pragma once
#include <string>
#include <string_view>

namespace pineda::shader {

inline std::string compile_error(int string, int line, std::string_view what, std::string_view why) {
  return "ERROR: " + std::to_string(string) + ":" + std::to_string(line) + ": '" + std::string(what) + "' : " +
         std::string(why) + "\nERROR: 1 compilation errors.  No code generated.\n\n\n";
}

}  // namespace pineda::shader
