// The programmable part of a draw snapshot: the linked program and a copy of its uniform
// values (the draw runs later on worker threads while the application changes them).
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
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
    return computed(fragment_uniform_values_, &shader::Program::fragment_uniform_values);
  }
  // Makes a ShaderDraw that nothing else holds (a pool's: state/programs/shader_draw_pool.h) as
  // a new one but for its program and uniforms, which the next draw sets: no facing, colour 0,
  // no stage values yet (their vectors keep their room).
  void prepare_for_reuse() {
    two_side = false;
    color_output = 0;
    fragment_uniform_values_.state.store(kNotComputed, std::memory_order_relaxed);
    vertex_uniform_values_.state.store(kNotComputed, std::memory_order_relaxed);
  }
  // The same of the vertex shader, computed by the first run that asks: a draw whose uniforms
  // are unchanged shares the last draw's ShaderDraw, and so these (glsl_small_draws computed
  // them per draw).
  const float* vertex_uniform_values() const {
    return computed(vertex_uniform_values_, &shader::Program::vertex_uniform_values);
  }

 private:
  enum : uint8_t { kNotComputed, kComputing, kComputed };
  // A copy (a draw that changes some uniforms) starts without values.
  struct UniformValues {
    std::atomic<uint8_t> state{kNotComputed};
    std::vector<float> values;
    UniformValues() = default;
    UniformValues(const UniformValues&) {}
    UniformValues& operator=(const UniformValues&) { return *this; }
  };
  mutable UniformValues fragment_uniform_values_, vertex_uniform_values_;

  using ComputeValues = void (shader::Program::*)(const float* uniforms, std::vector<float>& out) const;
  const float* computed(UniformValues& values, ComputeValues compute) const {
    // Once computed, a load (every quad row asks). The first asker claims the computing with
    // one compare-and-swap; one that finds it claimed waits for it. Not std::call_once: glibc's
    // pthread_once ends every first call with a futex wake system call, once per draw here
    // (2-3% of glmark2's ideas scene, many small draws, under this VM's costly system calls);
    // not a mutex: its lock and unlock were two atomic operations on a line the pool's threads
    // had written, about 3% of glsl_many_draws' calling thread with two threads.
    if (values.state.load(std::memory_order_acquire) != kComputed) {
      uint8_t expected = kNotComputed;
      if (values.state.compare_exchange_strong(expected, kComputing, std::memory_order_acquire)) {
        try {
          if (program) (*program.*compute)(uniforms.data(), values.values);
        } catch (...) {  // (std::bad_alloc) the next asker tries again; none waits forever
          values.state.store(kNotComputed, std::memory_order_release);
          throw;
        }
        values.state.store(kComputed, std::memory_order_release);
      } else {
        // Until computed, or given up (then this one computes, as the first asker would have).
        while ((expected = values.state.load(std::memory_order_acquire)) == kComputing) std::this_thread::yield();
        if (expected != kComputed) return computed(values, compute);
      }
    }
    return values.values.empty() ? nullptr : values.values.data();
  }
};

}  // namespace pineda::raster
