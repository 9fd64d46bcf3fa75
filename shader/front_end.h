// The glslang front end: one-time process initialisation, GL 2.1 / ES 2.0 resource limits,
// and parsing of a shader's sources into a TShader.
#pragma once
#include <memory>
#include <mutex>
#include <string>

#include <glslang/Public/ShaderLang.h>

#include "shader/compiled_shader.h"

namespace pineda::shader::front_end {

// glslang keeps process-wide tables (built-in symbol tables) that are not safe to build
// from two threads at once: every parse and link runs under this lock.
std::mutex& glslang_lock();

// Parses `shader`'s sources (glslang must be locked). Returns null and sets `log` on
// failure; `log` holds glslang's info log either way.
std::unique_ptr<glslang::TShader> parse(const CompiledShader& shader, std::string& log);

EShLanguage stage_of(Stage stage);

}  // namespace pineda::shader::front_end
