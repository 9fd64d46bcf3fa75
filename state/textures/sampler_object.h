// Sampler objects (GL_ARB_sampler_objects): a texture's sampling parameters as an object of
// their own (textures/sampling_params.h), named in the share group's name space. One bound to
// a texture unit replaces the sampling parameters of every texture that unit reads.
#pragma once
#include <GL/gl.h>

#include <map>
#include <memory>

#include "state/textures/texture_object.h"

namespace pineda {

struct SamplerObject {
  TexParams params;  // the sampling parameters only; the others keep their initial values
};

// A unit holds its sampler by shared_ptr: another context deleting the name leaves it bound.
using SamplerNames = std::map<GLuint, std::shared_ptr<SamplerObject>>;

}  // namespace pineda
