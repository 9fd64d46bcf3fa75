// What a glGet* query returns before conversion to the caller's type (api_get.cpp), for the
// files that answer part of the queries.
#pragma once
#include <GL/gl.h>

#include <initializer_list>
#include <vector>

namespace pineda {

class Context;

enum class GetKind { Int, Enum, Bool, Float, Color };  // Color: [0,1] values that map to the int range

struct GetValues {
  GetKind kind = GetKind::Int;
  std::vector<double> v;
};

inline GetValues get_ints(std::initializer_list<double> v) { return {GetKind::Int, v}; }
inline GetValues get_enums(std::initializer_list<double> v) { return {GetKind::Enum, v}; }
inline GetValues get_bools(std::initializer_list<double> v) { return {GetKind::Bool, v}; }
inline GetValues get_floats(std::initializer_list<double> v) { return {GetKind::Float, v}; }

// Raster position, pixel transfer, zoom and pixel-map sizes (api_get_pixel_state.cpp).
bool query_pixel_state(Context& ctx, unsigned pname, GetValues& out);

// What glGet* returns for `pname` before conversion (api_get.cpp); false for an unknown pname.
bool query_get_values(Context& ctx, unsigned pname, GetValues& out);

// The queries only OpenGL ES 1.1 has (state/es1/es1_get.cpp).
bool query_es1(Context& ctx, unsigned pname, GetValues& out);

// The queries only OpenGL ES 2.0 has (state/es2/es2_get.cpp).
bool query_es2(Context& ctx, unsigned pname, GetValues& out);

// The GL_KHR_debug limits, log size and debug group depth (state/debug/debug_get.cpp).
bool query_debug(Context& ctx, unsigned pname, GetValues& out);

// NUM_COMPRESSED_TEXTURE_FORMATS and COMPRESSED_TEXTURE_FORMATS (api_compressed_texture.cpp).
bool query_compressed_formats(const Context& ctx, unsigned pname, GetValues& out);

}  // namespace pineda
