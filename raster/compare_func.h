// The comparison functions of the depth, stencil and alpha tests and of shadow textures.
#pragma once
#include <cstdint>

namespace pineda::raster {

enum class CompareFunc : uint8_t { Never, Less, Equal, LessEqual, Greater, NotEqual, GreaterEqual, Always };

}  // namespace pineda::raster
