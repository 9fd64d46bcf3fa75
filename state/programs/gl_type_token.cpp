#include "state/programs/gl_type_token.h"

#include <GL/glext.h>

namespace pineda {

GLenum gl_type_token(const shader::Type& t) {
  const int n = t.rows;
  switch (t.base) {
    case shader::BaseType::Float: {
      if (t.columns >= 2) {
        static constexpr GLenum kMat[3][3] = {  // [columns - 2][rows - 2]
            {GL_FLOAT_MAT2, GL_FLOAT_MAT2x3, GL_FLOAT_MAT2x4},
            {GL_FLOAT_MAT3x2, GL_FLOAT_MAT3, GL_FLOAT_MAT3x4},
            {GL_FLOAT_MAT4x2, GL_FLOAT_MAT4x3, GL_FLOAT_MAT4}};
        if (n >= 2 && n <= 4 && t.columns <= 4) return kMat[t.columns - 2][n - 2];
        return GL_FLOAT;
      }
      static constexpr GLenum kVec[4] = {GL_FLOAT, GL_FLOAT_VEC2, GL_FLOAT_VEC3, GL_FLOAT_VEC4};
      return n >= 1 && n <= 4 ? kVec[n - 1] : GL_FLOAT;
    }
    case shader::BaseType::Int: {
      static constexpr GLenum kVec[4] = {GL_INT, GL_INT_VEC2, GL_INT_VEC3, GL_INT_VEC4};
      return n >= 1 && n <= 4 ? kVec[n - 1] : GL_INT;
    }
    case shader::BaseType::Bool: {
      static constexpr GLenum kVec[4] = {GL_BOOL, GL_BOOL_VEC2, GL_BOOL_VEC3, GL_BOOL_VEC4};
      return n >= 1 && n <= 4 ? kVec[n - 1] : GL_BOOL;
    }
    case shader::BaseType::Sampler1D: return GL_SAMPLER_1D;
    case shader::BaseType::Sampler2D: return GL_SAMPLER_2D;
    case shader::BaseType::Sampler3D: return GL_SAMPLER_3D;
    case shader::BaseType::SamplerCube: return GL_SAMPLER_CUBE;
    case shader::BaseType::Sampler1DShadow: return GL_SAMPLER_1D_SHADOW;
    case shader::BaseType::Sampler2DShadow: return GL_SAMPLER_2D_SHADOW;
    case shader::BaseType::Sampler2DRect: return GL_SAMPLER_2D_RECT_ARB;
    case shader::BaseType::Sampler2DRectShadow: return GL_SAMPLER_2D_RECT_SHADOW_ARB;
  }
  return GL_FLOAT;
}

}  // namespace pineda
