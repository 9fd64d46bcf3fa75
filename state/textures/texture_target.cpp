#include "state/textures/texture_target.h"

#include <bit>

#include "state/context.h"
#include "state/limits.h"

namespace pineda {

bool image_target(GLenum target, ImageTarget& out) {
  out = ImageTarget{};
  switch (target) {
    case GL_TEXTURE_1D: out.kind = TexTarget::T1D; return true;
    case GL_TEXTURE_2D: out.kind = TexTarget::T2D; return true;
    case GL_TEXTURE_3D: out.kind = TexTarget::T3D; return true;
    case GL_PROXY_TEXTURE_1D: out = {TexTarget::T1D, true, 0}; return true;
    case GL_PROXY_TEXTURE_2D: out = {TexTarget::T2D, true, 0}; return true;
    case GL_PROXY_TEXTURE_3D: out = {TexTarget::T3D, true, 0}; return true;
    case GL_PROXY_TEXTURE_CUBE_MAP: out = {TexTarget::Cube, true, 0}; return true;
    case GL_TEXTURE_RECTANGLE_ARB: out.kind = TexTarget::Rect; return true;
    case GL_PROXY_TEXTURE_RECTANGLE_ARB: out = {TexTarget::Rect, true, 0}; return true;
    default:
      if (target < GL_TEXTURE_CUBE_MAP_POSITIVE_X || target > GL_TEXTURE_CUBE_MAP_NEGATIVE_Z) return false;
      out = {TexTarget::Cube, false, int(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X)};
      return true;
  }
}

bool binding_target(GLenum target, TexTarget& out) {
  switch (target) {
    case GL_TEXTURE_1D: out = TexTarget::T1D; return true;
    case GL_TEXTURE_2D: out = TexTarget::T2D; return true;
    case GL_TEXTURE_3D: out = TexTarget::T3D; return true;
    case GL_TEXTURE_CUBE_MAP: out = TexTarget::Cube; return true;
    case GL_TEXTURE_RECTANGLE_ARB: out = TexTarget::Rect; return true;
    default: return false;
  }
}

GLenum binding_enum(TexTarget kind) {
  switch (kind) {
    case TexTarget::T1D: return GL_TEXTURE_1D;
    case TexTarget::T2D: return GL_TEXTURE_2D;
    case TexTarget::T3D: return GL_TEXTURE_3D;
    case TexTarget::Cube: return GL_TEXTURE_CUBE_MAP;
    case TexTarget::Rect: return GL_TEXTURE_RECTANGLE_ARB;
  }
  return GL_TEXTURE_2D;
}

int image_dimensions(TexTarget kind) {
  switch (kind) {
    case TexTarget::T1D: return 1;
    case TexTarget::T3D: return 3;
    default: return 2;
  }
}

int max_texture_size(TexTarget kind) {
  switch (kind) {
    case TexTarget::T3D: return kMax3DTextureSize;
    case TexTarget::Cube: return kMaxCubeMapTextureSize;
    case TexTarget::Rect: return kMaxRectangleTextureSize;
    default: return kMaxTextureSize;
  }
}

int max_texture_level(TexTarget kind) {
  return kind == TexTarget::Rect ? 0 : std::bit_width(unsigned(max_texture_size(kind))) - 1;
}

GLuint& bound_name(TextureUnitState& unit, TexTarget kind) {
  switch (kind) {
    case TexTarget::T1D: return unit.bound_1d;
    case TexTarget::T3D: return unit.bound_3d;
    case TexTarget::Cube: return unit.bound_cube;
    case TexTarget::Rect: return unit.bound_rect;
    default: return unit.bound_2d;
  }
}

bool& enabled_flag(TextureUnitState& unit, TexTarget kind) {
  switch (kind) {
    case TexTarget::T1D: return unit.enabled_1d;
    case TexTarget::T3D: return unit.enabled_3d;
    case TexTarget::Cube: return unit.enabled_cube;
    case TexTarget::Rect: return unit.enabled_rect;
    default: return unit.enabled_2d;
  }
}

}  // namespace pineda
