// Enum lists that several tables of fuzzed calls draw from.
#pragma once
#include <GL/gl.h>
#include <GL/glext.h>


namespace pineda::fuzz {

// OpenGL ES 1.1 names that desktop GL's headers lack.
inline constexpr GLenum kTextureCropRectOes = 0x8B9D;  // OES_draw_texture
inline constexpr GLenum kTextureGenStrOes = 0x8D60;    // OES_texture_cube_map

inline constexpr GLenum kTextureUnits[] = {GL_TEXTURE0, GL_TEXTURE1, GL_TEXTURE3, GL_TEXTURE7, GL_TEXTURE31};
inline constexpr GLenum kFogNames[] = {GL_FOG_MODE, GL_FOG_DENSITY, GL_FOG_START, GL_FOG_END, GL_FOG_INDEX,
                                       GL_FOG_COLOR, GL_FOG_COORD_SRC};
inline constexpr GLenum kLightModelNames[] = {GL_LIGHT_MODEL_AMBIENT, GL_LIGHT_MODEL_LOCAL_VIEWER,
                                              GL_LIGHT_MODEL_TWO_SIDE, GL_LIGHT_MODEL_COLOR_CONTROL};
inline constexpr GLenum kPointParameterNames[] = {GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX, GL_POINT_FADE_THRESHOLD_SIZE,
                                                  GL_POINT_DISTANCE_ATTENUATION, GL_POINT_SPRITE_COORD_ORIGIN};
inline constexpr GLenum kPixelTransferNames[] = {GL_MAP_COLOR,   GL_MAP_STENCIL, GL_INDEX_SHIFT,
                                                 GL_INDEX_OFFSET, GL_RED_SCALE,   GL_GREEN_BIAS,
                                                 GL_ALPHA_SCALE,  GL_DEPTH_SCALE, GL_DEPTH_BIAS};
inline constexpr GLenum kLights[] = {GL_LIGHT0, GL_LIGHT1, GL_LIGHT7};
inline constexpr GLenum kLightNames[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_POSITION, GL_SPOT_DIRECTION,
                                         GL_SPOT_EXPONENT, GL_SPOT_CUTOFF, GL_CONSTANT_ATTENUATION,
                                         GL_LINEAR_ATTENUATION, GL_QUADRATIC_ATTENUATION};
inline constexpr GLenum kMaterialFaces[] = {GL_FRONT, GL_BACK, GL_FRONT_AND_BACK};
inline constexpr GLenum kMaterialNames[] = {GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION, GL_SHININESS,
                                            GL_AMBIENT_AND_DIFFUSE, GL_COLOR_INDEXES};
inline constexpr GLenum kTexEnvTargets[] = {GL_TEXTURE_ENV, GL_TEXTURE_FILTER_CONTROL, GL_POINT_SPRITE};
inline constexpr GLenum kTexEnvNames[] = {GL_TEXTURE_ENV_MODE, GL_TEXTURE_ENV_COLOR, GL_COMBINE_RGB,
                                          GL_SOURCE2_ALPHA,    GL_RGB_SCALE,         GL_TEXTURE_LOD_BIAS,
                                          GL_COORD_REPLACE,    GL_OPERAND1_RGB};
inline constexpr GLenum kTextureTargets[] = {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP,
                                             GL_TEXTURE_RECTANGLE_ARB};
inline constexpr GLenum kTexParameterNames[] = {
    GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER,  GL_TEXTURE_WRAP_S,     GL_TEXTURE_WRAP_T,
    GL_TEXTURE_WRAP_R,     GL_TEXTURE_MIN_LOD,     GL_TEXTURE_MAX_LOD,    GL_TEXTURE_BASE_LEVEL,
    GL_TEXTURE_MAX_LEVEL,  GL_TEXTURE_LOD_BIAS,    GL_GENERATE_MIPMAP,    GL_TEXTURE_PRIORITY,
    GL_DEPTH_TEXTURE_MODE, GL_TEXTURE_COMPARE_MODE, GL_TEXTURE_COMPARE_FUNC, GL_TEXTURE_BORDER_COLOR,
    GL_TEXTURE_RESIDENT,   kTextureCropRectOes};
inline constexpr GLenum kTexGenCoords[] = {GL_S, GL_T, GL_R, GL_Q, kTextureGenStrOes};
inline constexpr GLenum kTexGenNames[] = {GL_TEXTURE_GEN_MODE, GL_OBJECT_PLANE, GL_EYE_PLANE};
inline constexpr GLenum kCompareFunctions[] = {GL_NEVER,    GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                                               GL_GREATER,  GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
inline constexpr GLenum kClipPlanes[] = {GL_CLIP_PLANE0, GL_CLIP_PLANE3, GL_CLIP_PLANE5, GL_CLIP_PLANE0 + 6};

}  // namespace pineda::fuzz
