// The programmable part of a draw snapshot: the linked program and a copy of its uniform
// values (the draw runs later on worker threads while the application changes them).
#pragma once
#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "shader/program.h"

namespace pineda::raster {

struct ShaderDraw {
  std::shared_ptr<const shader::Program> program;
  std::vector<float> uniforms;  // program->uniform_floats() values
  bool two_side = false;        // back-facing polygons read the varyings' back_offset values
  int color_output = 0;         // the gl_FragData index written to the colour buffer

  // program->fragment_uniform_values(uniforms), computed by the first block that asks (on any
  // worker thread); null when the fragment shader has none.
  const float* fragment_uniform_values() const {
    // Once computed, a flag read (every quad row asks). A mutex, not std::call_once: glibc's
    // pthread_once ends every first call with a futex wake system call, once per draw here
    // (2-3% of glmark2's ideas scene, many small draws, under this VM's costly system calls).
    if (!uniform_values_.ready.load(std::memory_order_acquire)) {
      const std::lock_guard lock(uniform_values_.mutex);
      if (!uniform_values_.ready.load(std::memory_order_relaxed)) {
        if (program) program->fragment_uniform_values(uniforms.data(), uniform_values_.values);
        uniform_values_.ready.store(true, std::memory_order_release);
      }
    }
    return uniform_values_.values.empty() ? nullptr : uniform_values_.values.data();
  }

 private:
  // A copy (a draw that changes some uniforms) starts without values.
  struct UniformValues {
    std::mutex mutex;
    std::atomic<bool> ready{false};
    std::vector<float> values;
    UniformValues() = default;
    UniformValues(const UniformValues&) {}
    UniformValues& operator=(const UniformValues&) { return *this; }
  };
  mutable UniformValues uniform_values_;
};

}  // namespace pineda::raster
