// Queries into memory exactly as large as what they write, so that AddressSanitizer reports
// a value written past it: the number of values per query name, and the calls made with it.
#pragma once
#include <GL/gl.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tests/fuzz/fuzz_input.h"
#include "tests/fuzz/gl_enum_lists.h"

namespace pineda::fuzz {

// A query's name and the number of values it writes.
struct QueryName {
  GLenum name;
  size_t count;
};

// One of `names` (7 times in 8), otherwise an enum no query takes (it writes nothing).
inline QueryName query_name(FuzzInput& in, std::span<const QueryName> names) {
  const uint8_t pick = in.byte();
  if (pick % 8 != 7) return names[(pick / 8) % names.size()];
  return {in.enumeration({}), 1};
}

// The values glGetLight, glGetMaterial, glGetTexEnv, glGetTexParameter and glGetTexGen write.
inline constexpr QueryName kLightQueries[] = {
    {GL_AMBIENT, 4},        {GL_DIFFUSE, 4},        {GL_SPECULAR, 4},
    {GL_POSITION, 4},       {GL_SPOT_DIRECTION, 3}, {GL_SPOT_EXPONENT, 1},
    {GL_SPOT_CUTOFF, 1},    {GL_CONSTANT_ATTENUATION, 1}, {GL_LINEAR_ATTENUATION, 1},
    {GL_QUADRATIC_ATTENUATION, 1}};
inline constexpr QueryName kMaterialQueries[] = {{GL_AMBIENT, 4},  {GL_DIFFUSE, 4},   {GL_SPECULAR, 4},
                                                 {GL_EMISSION, 4}, {GL_SHININESS, 1}, {GL_COLOR_INDEXES, 3}};
inline constexpr QueryName kTexEnvQueries[] = {{GL_TEXTURE_ENV_MODE, 1}, {GL_TEXTURE_ENV_COLOR, 4},
                                               {GL_COMBINE_RGB, 1},      {GL_SOURCE2_ALPHA, 1},
                                               {GL_RGB_SCALE, 1},        {GL_TEXTURE_LOD_BIAS, 1},
                                               {GL_COORD_REPLACE, 1},    {GL_OPERAND1_RGB, 1}};
inline constexpr QueryName kTexParameterQueries[] = {
    {GL_TEXTURE_MIN_FILTER, 1}, {GL_TEXTURE_WRAP_R, 1},      {GL_TEXTURE_BORDER_COLOR, 4},
    {GL_TEXTURE_MAX_LEVEL, 1},  {GL_GENERATE_MIPMAP, 1},     {GL_TEXTURE_COMPARE_FUNC, 1},
    {GL_TEXTURE_RESIDENT, 1},   {GL_TEXTURE_PRIORITY, 1},    {GL_TEXTURE_MIN_LOD, 1},
    {kTextureCropRectOes, 4}};
inline constexpr QueryName kTexGenQueries[] = {{GL_TEXTURE_GEN_MODE, 1}, {GL_OBJECT_PLANE, 4}, {GL_EYE_PLANE, 4}};

// Context state for glGetBooleanv, glGetDoublev and glGetFixedv: vectors, matrices and
// scalars, some set from NaN or 1e30. GL_COMPRESSED_TEXTURE_FORMATS writes as many values as
// GL_NUM_COMPRESSED_TEXTURE_FORMATS says (state_query).
inline constexpr QueryName kStateQueries[] = {
    {GL_CURRENT_COLOR, 4},        {GL_CURRENT_RASTER_POSITION, 4}, {GL_MODELVIEW_MATRIX, 16},
    {GL_PROJECTION_MATRIX, 16},   {GL_TEXTURE_MATRIX, 16},         {GL_TRANSPOSE_MODELVIEW_MATRIX, 16},
    {GL_VIEWPORT, 4},             {GL_MAX_TEXTURE_SIZE, 1},        {GL_LIST_INDEX, 1},
    {GL_TEXTURE_BINDING_2D, 1},   {GL_FOG_COLOR, 4},               {GL_LIGHT_MODEL_AMBIENT, 4},
    {GL_POLYGON_MODE, 2},         {GL_MAP1_GRID_DOMAIN, 2},        {GL_MAP2_GRID_DOMAIN, 4},
    {GL_MAP2_GRID_SEGMENTS, 2},   {GL_ACCUM_CLEAR_VALUE, 4},       {GL_DEPTH_RANGE, 2},
    {GL_SCISSOR_BOX, 4},          {GL_COLOR_WRITEMASK, 4},         {GL_CURRENT_NORMAL, 3},
    {GL_CURRENT_TEXTURE_COORDS, 4}, {GL_CURRENT_SECONDARY_COLOR, 4}, {GL_CURRENT_FOG_COORD, 1},
    {GL_CURRENT_INDEX, 1},        {GL_CURRENT_RASTER_COLOR, 4},    {GL_CURRENT_RASTER_TEXTURE_COORDS, 4},
    {GL_POINT_DISTANCE_ATTENUATION, 3}, {GL_ALIASED_POINT_SIZE_RANGE, 2}, {GL_MAX_VIEWPORT_DIMS, 2},
    {GL_LINE_WIDTH, 1},           {GL_POINT_SIZE, 1},              {GL_FOG_DENSITY, 1},
    {GL_FOG_END, 1},              {GL_ALPHA_TEST_REF, 1},          {GL_BLEND_COLOR, 4},
    {GL_ZOOM_X, 1},               {GL_INDEX_OFFSET, 1},            {GL_DEPTH_CLEAR_VALUE, 1},
    {GL_POLYGON_OFFSET_FACTOR, 1}, {GL_STENCIL_VALUE_MASK, 1},     {GL_MAX_TEXTURE_UNITS, 1},
    {GL_SAMPLE_COVERAGE_VALUE, 1}, {GL_COLOR_CLEAR_VALUE, 4},      {GL_COMPRESSED_TEXTURE_FORMATS, 0}};

// One of kStateQueries, with GL_COMPRESSED_TEXTURE_FORMATS's count asked of the context.
inline QueryName state_query(FuzzInput& in) {
  QueryName query = query_name(in, kStateQueries);
  if (query.name == GL_COMPRESSED_TEXTURE_FORMATS) {
    GLint formats = 0;
    glGetIntegerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &formats);
    query.count = size_t(formats > 0 ? formats : 0);
  }
  return query;
}

// glGetDoublev and the like.
template <typename T>
void get_state(FuzzInput& in, void (*get)(GLenum, T*)) {
  const QueryName query = state_query(in);
  std::vector<T> out(query.count + (query.count == 0));  // an address even for no values
  get(query.name, out.data());
}

// glGetLightfv and the like: a target of `targets`, a query of `names`.
template <typename T>
void sized_get(FuzzInput& in, void (*get)(GLenum, GLenum, T*), std::span<const GLenum> targets,
               std::span<const QueryName> names) {
  const GLenum target = in.enumeration(targets);
  const QueryName query = query_name(in, names);
  std::vector<T> out(query.count);
  get(target, query.name, out.data());
}

// glGetClipPlane and the like: the four coefficients of a plane.
template <typename T>
void get_clip_plane(FuzzInput& in, void (*get)(GLenum, T*)) {
  std::vector<T> out(4);
  get(in.enumeration(kClipPlanes), out.data());
}

}  // namespace pineda::fuzz
