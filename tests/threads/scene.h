// The deterministic scene every thread renders: fixed-function triangles with a texture,
// depth test and blending, then a GLSL program drawing from a buffer object; each frame
// turns the geometry a little further. Identical inputs give identical images.
#pragma once
#include <cstdint>
#include <vector>

namespace pineda::threads_test {

inline constexpr int kWidth = 96, kHeight = 80;  // spans several 64x64 tiles

// The objects the scene draws with: shared between contexts or each context's own.
struct SceneObjects {
  unsigned texture = 0, buffer = 0, program = 0;
};

// Creates them in the current context; program == 0 if it failed to compile or link.
SceneObjects create_scene_objects();
void delete_scene_objects(const SceneObjects& objects);

// Draws frame `frame` in the current context and reads the image back (RGBA8, bottom row first).
std::vector<uint8_t> render_frame(const SceneObjects& objects, int frame);

// FNV-1a 64 of the bytes.
uint64_t image_hash(const std::vector<uint8_t>& image);

// Renders `frames` frames; the hash of each frame's image, in order.
std::vector<uint64_t> render_frames(const SceneObjects& objects, int frames);

}  // namespace pineda::threads_test
