#define GL_GLEXT_PROTOTYPES
#include "multisample_target.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdio>

namespace pineda::demo {

MultisampleTarget makeMultisampleTarget(const char* scene, int width, int height, int samples) {
  MultisampleTarget t;
  glGenRenderbuffers(1, &t.color);
  glBindRenderbuffer(GL_RENDERBUFFER, t.color);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &t.depth);
  glBindRenderbuffer(GL_RENDERBUFFER, t.depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
  glGenFramebuffers(1, &t.framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, t.framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t.color);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, t.depth);
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    std::fprintf(stderr, "%s: the multisampled framebuffer object is not complete\n", scene);
  GLint actual = 0;
  glGetIntegerv(GL_SAMPLES, &actual);
  if (actual != samples) std::fprintf(stderr, "%s: GL_SAMPLES is %d, not %d\n", scene, actual, samples);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return t;
}

}  // namespace pineda::demo
