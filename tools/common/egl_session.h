#pragma once
// Headless EGL: a display (surfaceless platform when available), an RGBA8 + depth 24 +
// stencil 8 pbuffer, and desktop OpenGL or OpenGL ES contexts made current on it.
#include <EGL/egl.h>

#include <string>

namespace pineda::tools {

// The API and version a context is asked for.
enum class ContextApi { GL11, GL21, ES11, ES20 };

class EglSession {
 public:
  EglSession() = default;
  EglSession(const EglSession&) = delete;
  EglSession& operator=(const EglSession&) = delete;
  ~EglSession();

  // Returns false and sets `error` on failure.
  bool open(int width, int height, std::string& error);
  // Replaces the current context with a new one, so each scene starts from GL's initial state;
  // of the API `api` asks for.
  bool freshContext(std::string& error, ContextApi api = ContextApi::GL11);

 private:
  bool makeCurrent(std::string& error);
  void destroyContext();

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLConfig config_ = nullptr;
  EGLSurface surface_ = EGL_NO_SURFACE;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace pineda::tools
