#include "shader/function_rules.h"

#include "shader/compile_error.h"
#include "shader/function_definitions.h"

namespace pineda::shader {
namespace {

std::string error_line(const glslang::TSourceLoc& loc, const std::string& what, const char* why) {
  return compile_error(loc.string, loc.line, what, why);
}

// The first broken rule of definition `f`, as its error; empty when it keeps them all.
std::string broken_rule(glslang::TIntermAggregate* f, bool desktop110) {
  const std::string name(f->getName().c_str(), f->getName().find('('));
  if (f->getType().containsSampler())
    return error_line(f->getLoc(), name, "a function cannot return a sampler or a structure holding one");
  const auto& params = f->getSequence()[0]->getAsAggregate()->getSequence();
  for (TIntermNode* n : params) {
    const glslang::TIntermSymbol* p = n ? n->getAsSymbolNode() : nullptr;
    if (!p) continue;
    const auto q = p->getQualifier().storage;
    if (q != glslang::EvqOut && q != glslang::EvqInOut) continue;
    const std::string param = p->getName().c_str();
    if (p->getType().containsSampler())
      return error_line(p->getLoc(), param, "a sampler or a structure holding one cannot be an out or inout parameter");
    if (desktop110 && p->getType().isArray())
      return error_line(p->getLoc(), param, "an array cannot be an out or inout parameter in GLSL 1.10");
  }
  return {};
}

}  // namespace

bool function_rules_ok(const glslang::TIntermediate* tree, std::string& log) {
  if (!tree) return true;
  const bool desktop110 = tree->getProfile() != EEsProfile && tree->getVersion() == 110;
  for (glslang::TIntermAggregate* f : function_definitions(tree->getTreeRoot())) {
    const std::string error = broken_rule(f, desktop110);
    if (error.empty()) continue;
    log += error;
    return false;
  }
  return true;
}

}  // namespace pineda::shader
