// The texture targets (GL 1.3: 1D, 2D, 3D and cube map; ARB_texture_rectangle) and how the enums of the
// API name them.
#pragma once
#include <GL/gl.h>

#include <cstdint>

namespace pineda {

struct TextureUnitState;

enum class TexTarget : uint8_t { T1D, T2D, T3D, Cube, Rect };
constexpr int kTexTargetCount = 5;
constexpr int kCubeFaces = 6;

// What an image command or a level query (glTexImage*, glTexSubImage*, glGetTexImage,
// glGetTexLevelParameter) addresses: a texture kind, its proxy or not, and a cube face.
struct ImageTarget {
  TexTarget kind = TexTarget::T2D;
  bool proxy = false;
  int face = 0;  // 0 to 5 for the cube map faces (+X, -X, +Y, -Y, +Z, -Z), 0 otherwise
};

// TEXTURE_1D/2D/3D/RECTANGLE, their proxies, the six cube faces and PROXY_TEXTURE_CUBE_MAP.
bool image_target(GLenum target, ImageTarget& out);
// The targets of glBindTexture, glTexParameter and glEnable: TEXTURE_1D/2D/3D/CUBE_MAP/RECTANGLE.
bool binding_target(GLenum target, TexTarget& out);
GLenum binding_enum(TexTarget kind);
// Image dimensions of a kind: 1, 2 or 3 (a cube face is 2D).
int image_dimensions(TexTarget kind);
// MAX_TEXTURE_SIZE, MAX_3D_TEXTURE_SIZE, MAX_CUBE_MAP_TEXTURE_SIZE or MAX_RECTANGLE_TEXTURE_SIZE.
int max_texture_size(TexTarget kind);
// The largest level number an image of this kind can have (log2 of its maximum size; 0 for a
// rectangle, which has no mipmaps).
int max_texture_level(TexTarget kind);

// The texture name bound to `kind` on a unit, and whether the unit enables `kind`.
GLuint& bound_name(TextureUnitState& unit, TexTarget kind);
bool& enabled_flag(TextureUnitState& unit, TexTarget kind);

}  // namespace pineda
