// The ShaderDraws of a context's program draws, used again once every draw record holding one
// has let it go. A draw that changes a uniform (the usual "set the object's uniforms, draw" loop)
// took a new one, and with it up to four allocations (the object, its uniform values and the
// values each stage works out from them), freed when its record went, on whichever thread let it
// go (glsl_many_draws: 7% of a frame in malloc and free with one thread; with two, the fragment
// values a worker allocated and the calling thread freed made it slower than with one). One
// used again keeps its vectors' room.
#pragma once
#include <cstddef>
#include <memory>
#include <vector>

#include "raster/shader_draw.h"

namespace pineda {

class ShaderDrawPool {
 public:
  // A ShaderDraw that nothing else holds, for a program of `uniform_floats` uniform values: its
  // fields as a new one's but its vectors' room and `program`, which the caller sets (one kept
  // holds its last program until it is used again). Kept only for up to kMaxKeptUniformFloats
  // values: what the pool keeps is then about what the draws of two full scenes held at once.
  std::shared_ptr<raster::ShaderDraw> take(size_t uniform_floats);

 private:
  static constexpr size_t kMaxKeptUniformFloats = 256;  // 1 KiB
  // Kept: the ShaderDraws of the draws two scenes hold (Scene's kMaxDraws each) and some more.
  // Draws let theirs go about in the order they were made, so the next one looked at was taken
  // about kept_.size() draws ago.
  static constexpr size_t kMaxKept = 9000;
  std::vector<std::shared_ptr<raster::ShaderDraw>> kept_;
  size_t next_ = 0;
};

}  // namespace pineda
