#include "bench_scene.h"

namespace pineda::bench {

const std::vector<BenchSceneEntry>& allBenchScenes() {
  static const std::vector<BenchSceneEntry> scenes = {
      {"overdraw", "64 full-screen depth-tested layers: 32 front-to-back, then 32 back-to-front", createOverdraw},
      {"blend", "32 full-screen alpha-blended smooth-shaded layers", createBlend},
      {"small_tris", "500k small triangles, glDrawElements with client arrays, depth test", createSmallTris},
      {"textured", "perspective corridor, trilinear mipmapped 256x256 textures", createTextured},
      {"lit_mesh", "smooth-shaded torus and sphere, GL_LIGHTING with 2 lights, specular", createLitMesh},
      {"gears", "pineda-demo's glxgears-like gears (display lists, lighting)", createGears},
      {"state_changes", "6144 one-quad draw calls changing colour, blend, depth func, texture", createStateChanges},
      {"small_draws", "20000 one-triangle glDrawArrays from a buffer object, no state change between them",
       createSmallDraws},
      {"copy_blur", "blur by glCopyTexSubImage2D of the frame, blended back shifted, 4 times a frame", createCopyBlur},
      {"read_pixels", "a smooth-shaded frame read back by glReadPixels as GL_RGBA and as GL_RGB bytes", createReadPixels},
      {"draw_pixels", "a window-sized RGBA byte image by glDrawPixels, then a quarter-size RGB one over it at pixel zoom 2",
       createDrawPixels},
      {"pixel_transfers", "glGetTexImage, glReadPixels of depth, stencil and float colour, glCopyPixels, float glDrawPixels, 1200 glBitmap glyphs",
       createPixelTransfers},
      {"texture_upload", "two 512x512 textures given new texels by glTexSubImage2D every frame (RGBA bytes, BGRA 8_8_8_8_REV)",
       createTextureUpload},
      {"wireframe", "a 64x64 height field as 130 line strips and 4225 two-pixel points, depth test", createWireframe},
      {"stencil_reflection", "a mirror through the stencil buffer: 24 lit cubes drawn reflected, blended floor, upright",
       createStencilReflection},
      {"glsl_lit", "GLSL: 6 full-screen layers lit per pixel (normalize, pow, texture2D); first = compile+link+frame",
       createGlslLit},
      {"glsl_skinned", "GLSL: 204800 triangles skinned by 4 of 8 bone matrices in the vertex shader; first = link+frame",
       createGlslSkinned},
      {"glsl_procedural", "GLSL: 2 full-screen layers of a long procedural shader (6 octaves of value noise)",
       createGlslProcedural},
      {"glsl_sprites", "GLSL: 6000 alpha-blended textured sprites with discard, one draw", createGlslSprites},
      {"glsl_rtt", "GLSL: 16 lit quads into a 512x512 texture FBO, composited twice with a 5-tap blur",
       createGlslRenderToTexture},
      {"glsl_many_draws", "GLSL: 12288 one-quad draws, two glUniform calls before each", createGlslManyDraws},
      {"glsl_small_draws", "GLSL: small_draws' 20000 one-triangle draws through one program, no uniform changed",
       createGlslSmallDraws},
      {"glsl_msaa", "GLSL: 2 full-screen layers of 8 texture taps and 64 thin triangles into a 4x multisampled FBO, resolved",
       createGlslMsaa},
  };
  return scenes;
}

const BenchSceneEntry* findBenchScene(std::string_view name) {
  for (const BenchSceneEntry& entry : allBenchScenes())
    if (entry.name == name) return &entry;
  return nullptr;
}

}  // namespace pineda::bench
