#pragma once
// Compiles and links a vertex and fragment shader for the shader scenes (desktop GL 2.x and
// OpenGL ES 2.0 share the calls); the logs of a failed compile or link go to stderr.
#include <initializer_list>

namespace pineda::demo {

// The program name. Attribute i is bound to the i-th of `attributes` before linking.
unsigned linkProgram(const char* scene, const char* vertexSource, const char* fragmentSource,
                     std::initializer_list<const char*> attributes = {});

}  // namespace pineda::demo
