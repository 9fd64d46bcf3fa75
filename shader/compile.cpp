// compile(): parse and validate with glslang; the tree is lowered at link time.
#include "shader/compiled_shader.h"
#include "shader/front_end.h"

namespace pineda::shader {

CompileResult compile(Stage stage, Language language, const std::vector<std::string>& sources) {
  auto shader = std::make_shared<CompiledShader>(CompiledShader{stage, language, sources});
  CompileResult result;
  std::lock_guard<std::mutex> hold(front_end::glslang_lock());
  if (front_end::parse(*shader, result.info_log)) result.shader = std::move(shader);
  return result;
}

}  // namespace pineda::shader
