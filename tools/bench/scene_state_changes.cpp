// Draw-call overhead: two layers of a 64x48 grid of small quads, one glDrawArrays per quad,
// and between the calls a colour change, blending on/off, a depth function change and a
// texture bind or texturing on/off.
#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "bench_scene.h"

namespace pineda::bench {
namespace {

constexpr int kColumns = 64, kRows = 48, kLayers = 2;
constexpr int kTextures = 4, kTextureSize = 16;

class StateChanges final : public BenchScene {
 public:
  StateChanges(int, int) {
    // Layer 1 is shifted by half a cell and lies nearer, across the middle of the depth range.
    for (int layer = 0; layer < kLayers; ++layer)
      for (int row = 0; row < kRows; ++row)
        for (int column = 0; column < kColumns; ++column) {
          const float shift = 0.5f * float(layer), inset = 0.08f;
          const float x0 = -1.0f + 2.0f * (float(column) + shift + inset) / kColumns;
          const float x1 = -1.0f + 2.0f * (float(column) + shift + 1 - inset) / kColumns;
          const float y0 = -1.0f + 2.0f * (float(row) + shift + inset) / kRows;
          const float y1 = -1.0f + 2.0f * (float(row) + shift + 1 - inset) / kRows;
          const float z = layer == 0 ? 0.0f : 0.4f - 0.8f * float(column) / kColumns;
          vertices_.insert(vertices_.end(), {x0, y0, z, x1, y0, z, x1, y1, z, x0, y1, z});
          texCoords_.insert(texCoords_.end(), {0, 0, 1, 0, 1, 1, 0, 1});
        }
    glGenTextures(kTextures, textures_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int t = 0; t < kTextures; ++t) {
      std::vector<std::uint8_t> texels(kTextureSize * kTextureSize * 4);
      for (int i = 0; i < kTextureSize * kTextureSize; ++i) {
        const int x = i % kTextureSize, y = i / kTextureSize;
        const bool on = ((x >> (t % 2 + 1)) + (y >> (t / 2 + 1))) % 2 == 0;
        texels[i * 4 + 0] = on ? 255 : std::uint8_t(60 * t);
        texels[i * 4 + 1] = on ? 255 : 80;
        texels[i * 4 + 2] = on ? 255 : std::uint8_t(200 - 40 * t);
        texels[i * 4 + 3] = on ? 255 : 128;
      }
      glBindTexture(GL_TEXTURE_2D, textures_[t]);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, kTextureSize, kTextureSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, vertices_.data());
    glTexCoordPointer(2, GL_FLOAT, 0, texCoords_.data());
  }

  ~StateChanges() override { glDeleteTextures(kTextures, textures_); }

  void draw(int frame) override {
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);  // alpha stays 1, so the PNG shows the colours
    static constexpr GLenum kDepthFuncs[3] = {GL_LESS, GL_LEQUAL, GL_ALWAYS};
    for (int k = 0; k < quadCount(); ++k) {
      const int hue = (k * 37 + frame * 5) % 256;
      glColor4ub(GLubyte(hue), GLubyte(255 - hue), GLubyte((k * 11) % 256), k % 2 ? 160 : 255);
      if (k % 2) glEnable(GL_BLEND); else glDisable(GL_BLEND);
      glDepthFunc(kDepthFuncs[k % 3]);
      if (k % 4 == 3) {
        glDisable(GL_TEXTURE_2D);
      } else {
        glEnable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, textures_[(k / 4 + frame) % kTextures]);
      }
      glDrawArrays(GL_QUADS, 4 * k, 4);
    }
  }

  long trianglesPerFrame() const override { return 2L * quadCount(); }
  long drawCallsPerFrame() const override { return quadCount(); }

 private:
  static constexpr int quadCount() { return kColumns * kRows * kLayers; }

  std::vector<float> vertices_, texCoords_;
  GLuint textures_[kTextures] = {};
};

}  // namespace

std::unique_ptr<BenchScene> createStateChanges(int width, int height) {
  return std::make_unique<StateChanges>(width, height);
}

}  // namespace pineda::bench
