// Limits of the programmable pipeline that glGet reports.
#pragma once

namespace pineda {

// GL_MAX_VERTEX/FRAGMENT_UNIFORM_COMPONENTS: uniforms live in a float array of any size in
// the program; this is the amount GL 2.0 programs may count on (its minimum is 512 / 64).
constexpr int kMaxUniformComponents = 1024;

}  // namespace pineda
