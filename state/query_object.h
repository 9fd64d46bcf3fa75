// Occlusion queries (GL 1.5): each query owns the counter its draws add their samples to.
#pragma once
#include <GL/gl.h>

#include <cstdint>
#include <memory>

#include "raster/sample_counter.h"
#include "state/object_names.h"

namespace pineda {

struct QueryObject {
  explicit QueryObject(GLuint n) : name(n) {}
  GLuint name;
  // The draws between glBeginQuery and glEndQuery count here; null before the first query.
  std::shared_ptr<raster::SampleCounter> counter;
};

struct QueryState {
  ObjectNames<QueryObject> names;
  std::shared_ptr<QueryObject> active_samples_passed;  // GL_SAMPLES_PASSED
};

}  // namespace pineda
