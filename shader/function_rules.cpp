#include "shader/function_rules.h"

namespace pineda::shader {
namespace {

std::string error_line(const glslang::TSourceLoc& loc, const std::string& what, const std::string& why) {
  return "ERROR: " + std::to_string(loc.string) + ":" + std::to_string(loc.line) + ": '" + what + "' : " + why + "\n";
}

// The first broken rule of definition `f`, as a log line; empty when it keeps them all.
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
  glslang::TIntermAggregate* top = tree && tree->getTreeRoot() ? tree->getTreeRoot()->getAsAggregate() : nullptr;
  if (!top) return true;
  const bool desktop110 = tree->getProfile() != EEsProfile && tree->getVersion() == 110;
  for (TIntermNode* n : top->getSequence()) {
    glslang::TIntermAggregate* f = n ? n->getAsAggregate() : nullptr;
    if (!f || f->getOp() != glslang::EOpFunction) continue;
    const std::string error = broken_rule(f, desktop110);
    if (error.empty()) continue;
    log += error + "ERROR: 1 compilation errors.  No code generated.\n\n\n";
    return false;
  }
  return true;
}

}  // namespace pineda::shader
