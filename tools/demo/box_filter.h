#pragma once
// Mipmap levels for the demo scenes' textures, made on the CPU.
#include <cstdint>
#include <vector>

namespace pineda::demo {

using Texels = std::vector<std::uint8_t>;  // tightly packed, `channels` bytes a texel

// Box-filters a square level of `size` texels a side down to half its size (rounding).
Texels halve(const Texels& level, int size, int channels);

}  // namespace pineda::demo
