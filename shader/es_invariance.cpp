#include "shader/es_invariance.h"

#include <set>

namespace pineda::shader {
namespace {

// The built-in storage qualifiers of the symbols declared invariant in a tree (a
// redeclaration `invariant gl_Position;` marks the variable, so every later use carries it).
class InvariantBuiltins : public glslang::TIntermTraverser {
 public:
  std::set<glslang::TStorageQualifier> found;
  void visitSymbol(glslang::TIntermSymbol* s) override {
    if (s->getQualifier().invariant) found.insert(s->getQualifier().storage);
  }
};

std::set<glslang::TStorageQualifier> invariant_builtins(const glslang::TIntermediate* tree) {
  InvariantBuiltins t;
  if (tree && tree->getTreeRoot()) tree->getTreeRoot()->traverse(&t);
  return t.found;
}

}  // namespace

bool es_invariance_ok(const glslang::TIntermediate* vertex, const glslang::TIntermediate* fragment,
                      std::string& log) {
  if (!fragment) return true;
  const auto vs = invariant_builtins(vertex), fs = invariant_builtins(fragment);
  if (fs.count(glslang::EvqFace)) {
    log += "error: gl_FrontFacing cannot be declared invariant\n";
    return false;
  }
  if (fs.count(glslang::EvqFragCoord) && !vs.count(glslang::EvqPosition)) {
    log += "error: gl_FragCoord is invariant but gl_Position is not\n";
    return false;
  }
  if (fs.count(glslang::EvqPointCoord) && !vs.count(glslang::EvqPointSize)) {
    log += "error: gl_PointCoord is invariant but gl_PointSize is not\n";
    return false;
  }
  return true;
}

}  // namespace pineda::shader
