// glslang types as flattened VarTypes.
#include "shader/lowerer.h"

namespace pineda::shader::lowering {

namespace {

VarType var_type_of_element(const TType& t) {
  VarType v;
  if (t.isStruct()) {
    for (const glslang::TTypeLoc& m : *t.getStruct())
      v.members.emplace_back(m.type->getFieldName().c_str(), var_type(*m.type));
    return v;
  }
  switch (t.getBasicType()) {
    case glslang::EbtFloat: case glslang::EbtDouble: v.base = BaseType::Float; break;
    case glslang::EbtInt: case glslang::EbtUint: v.base = BaseType::Int; break;
    case glslang::EbtBool: v.base = BaseType::Bool; break;
    case glslang::EbtSampler: {
      const glslang::TSampler& s = t.getSampler();
      switch (s.dim) {
        case glslang::Esd1D: v.base = s.shadow ? BaseType::Sampler1DShadow : BaseType::Sampler1D; break;
        case glslang::Esd2D: v.base = s.shadow ? BaseType::Sampler2DShadow : BaseType::Sampler2D; break;
        case glslang::Esd3D: v.base = BaseType::Sampler3D; break;
        case glslang::EsdCube: v.base = BaseType::SamplerCube; break;
        case glslang::EsdRect: v.base = s.shadow ? BaseType::Sampler2DRectShadow : BaseType::Sampler2DRect; break;
        default: fail("error: unsupported sampler type\n");
      }
      break;
    }
    default: fail("error: unsupported type\n");
  }
  if (t.isMatrix()) {
    v.cols = t.getMatrixCols();
    v.rows = t.getMatrixRows();
  } else {
    v.rows = t.getVectorSize();
  }
  return v;
}

}  // namespace

VarType var_type(const TType& t, const std::string& name) {
  VarType v = var_type_of_element(t);
  if (t.isArray()) {
    // An unsized array (gl_TexCoord used with constant indices) has the size its highest
    // index implies.
    int n = t.isSizedArray() ? t.getOuterArraySize() : t.getImplicitArraySize();
    v.array = n < 1 ? 1 : (n > kMaxTextureCoords && name == "gl_TexCoord" ? kMaxTextureCoords : n);
  }
  return v;
}

}  // namespace pineda::shader::lowering
