#include "shader/front_end.h"

#include <glslang/Include/ResourceLimits.h>
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>

#include "shader/compile_error.h"
#include "shader/es_draw_buffers.h"
#include "shader/fragment_outputs.h"
#include "shader/function_rules.h"
#include "shader/tree_depth.h"

namespace pineda::shader::front_end {

namespace {

TBuiltInResource gl21_resources() {
  TBuiltInResource r = *GetDefaultResources();
  r.maxLights = 8;
  r.maxClipPlanes = 6;
  r.maxTextureUnits = 8;
  r.maxTextureCoords = 8;
  r.maxVertexAttribs = kMaxVertexAttribs;
  r.maxVertexUniformComponents = 1024;
  r.maxVaryingFloats = kMaxVaryingFloats;
  r.maxVertexTextureImageUnits = 8;
  r.maxCombinedTextureImageUnits = 16;
  r.maxTextureImageUnits = 8;
  r.maxFragmentUniformComponents = 1024;
  r.maxDrawBuffers = kMaxDrawBuffers;
  r.maxVertexUniformVectors = 256;
  r.maxVaryingVectors = kMaxVaryingFloats / 4;
  r.maxFragmentUniformVectors = 256;
  return r;
}

struct Process {
  Process() { glslang::InitializeProcess(); }
  std::mutex lock;
  TBuiltInResource resources = gl21_resources();
};

Process& process() {
  static Process p;
  return p;
}

}  // namespace

std::mutex& glslang_lock() { return process().lock; }

EShLanguage stage_of(Stage stage) { return stage == Stage::Vertex ? EShLangVertex : EShLangFragment; }

std::unique_ptr<glslang::TShader> parse(const CompiledShader& shader, std::string& log) {
  Process& p = process();
  auto sh = std::make_unique<glslang::TShader>(stage_of(shader.stage));
  const bool es = shader.language == Language::Es100;
  TBuiltInResource resources = p.resources;
  std::vector<std::string> sources = shader.sources;
  if (es) {  // an OpenGL ES 2.0 context, which has GL_EXT_draw_buffers
    resources.maxDrawBuffers = take_draw_buffers_directives(sources) ? kMaxDrawBuffers : 1;
    sh->setPreamble("#define GL_EXT_draw_buffers 1\n");
  }
  std::vector<const char*> strings;
  for (const std::string& s : sources) strings.push_back(s.c_str());
  const char* empty = "";
  if (strings.empty()) strings.push_back(empty);
  sh->setStrings(strings.data(), static_cast<int>(strings.size()));
  // GLSL 1.10/1.20 give vertex shaders texture*Lod; glslang 12 asks for the ARB extension
  // there, so it is enabled ahead of the user's source (no line moves). The rectangle samplers
  // (ARB_texture_rectangle) need no #extension line either, as in Mesa, which enables that
  // extension for every desktop shader.
  if (shader.language == Language::Desktop)
    sh->setPreamble(shader.stage == Stage::Vertex ? "#extension GL_ARB_texture_rectangle : enable\n"
                                                    "#extension GL_ARB_shader_texture_lod : enable\n"
                                                  : "#extension GL_ARB_texture_rectangle : enable\n");
  sh->setEnvInput(glslang::EShSourceGlsl, stage_of(shader.stage), glslang::EShClientNone, 100);
  sh->setEnvClient(glslang::EShClientNone, glslang::EShTargetClientVersion(0));
  sh->setEnvTarget(glslang::EShTargetNone, glslang::EShTargetLanguageVersion(0));
  bool ok = sh->parse(&resources, es ? 100 : 110, es ? EEsProfile : ENoProfile, false, false,
                      EShMsgDefault);
  log = sh->getInfoLog();
  if (!ok) return nullptr;
  const glslang::TIntermediate* tree = sh->getIntermediate();
  const int version = tree->getVersion();
  const bool tree_es = tree->getProfile() == EEsProfile;
  // Desktop GL takes GLSL ES 1.00 too (GL_ARB_ES2_compatibility, as Mesa).
  const bool supported = (tree_es && version == 100) || (!es && !tree_es && (version == 110 || version == 120));
  if (!supported) {
    log += compile_error(0, 1, "#version",
                         "version " + std::to_string(version) + (tree_es ? " es" : "") + " is not supported here (" +
                             (es ? "GLSL ES 1.00 only" : "GLSL 1.10, 1.20 and ES 1.00 only") + ")");
    return nullptr;
  }
  const int depth = tree_depth(tree->getTreeRoot());
  if (depth > kMaxTreeDepth) {
    log += compile_error(0, 0, "",
                         "expressions and statements nested too deeply (" + std::to_string(depth) + " levels, at most " +
                             std::to_string(kMaxTreeDepth) + ")");
    return nullptr;
  }
  if (!fragment_outputs_ok(tree, log) || !function_rules_ok(tree, log)) return nullptr;
  return sh;
}

}  // namespace pineda::shader::front_end
