#include "shader/fragment_outputs.h"

#include <map>
#include <string>

#include "shader/compile_error.h"
#include "shader/function_definitions.h"

namespace pineda::shader {
namespace {

bool is_assignment(glslang::TOperator op) {
  return (op >= glslang::EOpAssign && op <= glslang::EOpRightShiftAssign) ||
         (op >= glslang::EOpPostIncrement && op <= glslang::EOpPreDecrement);
}

// The variable an l-value expression writes: below its indexing, swizzles and fields.
glslang::TIntermSymbol* written_variable(TIntermNode* node) {
  while (glslang::TIntermBinary* b = node ? node->getAsBinaryNode() : nullptr) {
    const glslang::TOperator op = b->getOp();
    if (op != glslang::EOpIndexDirect && op != glslang::EOpIndexIndirect && op != glslang::EOpIndexDirectStruct &&
        op != glslang::EOpVectorSwizzle)
      break;
    node = b->getLeft();
  }
  return node ? node->getAsSymbolNode() : nullptr;
}

// Which of gl_FragColor and gl_FragData the tree assigns to, and where first.
class OutputWrites : public glslang::TIntermTraverser {
 public:
  explicit OutputWrites(const std::map<std::string, glslang::TIntermAggregate*>& functions) : functions_(functions) {}

  const glslang::TSourceLoc* color = nullptr;
  const glslang::TSourceLoc* data = nullptr;

  bool visitBinary(glslang::TVisit, glslang::TIntermBinary* b) override {
    if (is_assignment(b->getOp())) note(b->getLeft(), b->getLoc());
    return true;
  }
  bool visitUnary(glslang::TVisit, glslang::TIntermUnary* u) override {
    if (is_assignment(u->getOp())) note(u->getOperand(), u->getLoc());
    return true;
  }
  bool visitAggregate(glslang::TVisit, glslang::TIntermAggregate* a) override {
    if (a->getOp() != glslang::EOpFunctionCall || a->isUserDefined() == false) return true;
    auto it = functions_.find(a->getName().c_str());
    if (it == functions_.end()) return true;
    const auto& params = it->second->getSequence()[0]->getAsAggregate()->getSequence();
    const auto& args = a->getSequence();
    for (size_t i = 0; i < params.size() && i < args.size(); ++i) {
      const glslang::TIntermSymbol* p = params[i]->getAsSymbolNode();
      const auto q = p ? p->getQualifier().storage : glslang::EvqTemporary;
      if (q == glslang::EvqOut || q == glslang::EvqInOut) note(args[i], a->getLoc());
    }
    return true;
  }

 private:
  void note(TIntermNode* target, const glslang::TSourceLoc& loc) {
    const glslang::TIntermSymbol* s = written_variable(target);
    if (!s) return;
    // By name: glslang marks the built-in variables only when it makes SPIR-V (gl_ names are
    // reserved, so no user variable has them).
    const glslang::TString& name = s->getName();
    if (name == "gl_FragColor" && !color) color = &loc;
    if (name == "gl_FragData" && !data) data = &loc;
  }

  const std::map<std::string, glslang::TIntermAggregate*>& functions_;
};

}  // namespace

bool fragment_outputs_ok(const glslang::TIntermediate* tree, std::string& log) {
  if (!tree || !tree->getTreeRoot() || tree->getStage() != EShLangFragment) return true;
  std::map<std::string, glslang::TIntermAggregate*> functions;  // by glslang's (mangled) name
  for (glslang::TIntermAggregate* f : function_definitions(tree->getTreeRoot())) functions[f->getName().c_str()] = f;
  OutputWrites writes(functions);
  tree->getTreeRoot()->traverse(&writes);
  if (!writes.color || !writes.data) return true;
  const glslang::TSourceLoc& later = writes.color->line > writes.data->line ? *writes.color : *writes.data;
  log += compile_error(later.string, later.line, "gl_FragColor",
                       "a fragment shader may assign to gl_FragColor or to gl_FragData, not to both");
  return false;
}

}  // namespace pineda::shader
