// Client images for texture tests.
#pragma once
#include <cstdint>
#include <vector>

#include "tests/e2e/support/gl_test.h"

namespace pineda::test {

// `texels` RGBA8 texels of one colour.
inline std::vector<uint8_t> solid_texels(int texels, const Rgba& c) {
  std::vector<uint8_t> t;
  for (int i = 0; i < texels; ++i)
    for (int v : c) t.push_back(uint8_t(v));
  return t;
}

}  // namespace pineda::test
