// Cube map sampling (GL 1.3 3.8.6): the major axis of the direction (s, t, r) selects a face,
// which is sampled as a 2D image at ((sc / |ma| + 1) / 2, (tc / |ma| + 1) / 2), its wrap modes
// applied within the face (no filtering across faces).
#include <cmath>

#include "raster/mip_selection.h"
#include "raster/sampler_volume.h"
#include "raster/texel_addressing.h"

namespace pineda::raster {
namespace {

// Faces in the order of the GL targets: +X, -X, +Y, -Y, +Z, -Z.
int major_face(float rx, float ry, float rz) {
  const float ax = std::fabs(rx), ay = std::fabs(ry), az = std::fabs(rz);
  if (ax >= ay && ax >= az) return rx >= 0.f ? 0 : 1;
  if (ay >= az) return ry >= 0.f ? 2 : 3;
  return rz >= 0.f ? 4 : 5;
}

// The component of a direction along the major axis of `face`, signed so that it is positive
// for directions on that face's side.
float toward_face(int face, float rx, float ry, float rz) {
  const float v = face < 2 ? rx : (face < 4 ? ry : rz);
  return face & 1 ? -v : v;
}

// Table 3.19: the face coordinates of a direction on `face`.
void face_coords(int face, float rx, float ry, float rz, float& s, float& t) {
  float sc = 0.f, tc = 0.f, ma = 1.f;
  switch (face) {
    case 0: sc = -rz; tc = -ry; ma = rx; break;
    case 1: sc = rz; tc = -ry; ma = rx; break;
    case 2: sc = rx; tc = rz; ma = ry; break;
    case 3: sc = rx; tc = -rz; ma = ry; break;
    case 4: sc = rx; tc = -ry; ma = rz; break;
    default: sc = -rx; tc = -ry; ma = rz; break;
  }
  const float m = std::fabs(ma);
  s = m > 0.f ? sane((sc / m + 1.f) * 0.5f) : 0.5f;
  t = m > 0.f ? sane((tc / m + 1.f) * 0.5f) : 0.5f;
}

// The level of detail from the face coordinates of all four pixels projected on `face`.
float face_lambda(int size, int face, const float rx[4], const float ry[4], const float rz[4]) {
  float s[4], t[4];
  for (int i = 0; i < 4; ++i) face_coords(face, rx[i], ry[i], rz[i], s[i], t[i]);
  const float n = static_cast<float>(size);
  const float dudx = (s[1] - s[0]) * n, dvdx = (t[1] - t[0]) * n;
  const float dudy = (s[2] - s[0]) * n, dvdy = (t[2] - t[0]) * n;
  return lambda_from_rho2(std::max(dudx * dudx + dvdx * dvdx, dudy * dudy + dvdy * dvdy));
}

// The quad's level of detail: of the faces its pixels select, each one all four directions
// point toward (so that the projection is smooth), the least distorted, i.e. the smallest
// lambda. A quad reaching past a face's edge (helper pixels outside the primitive, or a
// primitive across a cube edge) so keeps the lambda of the face it mostly lies on.
float cube_lambda(int size, const int faces[4], const float rx[4], const float ry[4], const float rz[4]) {
  float best = NAN;
  for (int i = 0; i < 4; ++i) {
    const int f = faces[i];
    bool seen = false, toward = true;
    for (int k = 0; k < i; ++k) seen = seen || faces[k] == f;
    for (int k = 0; k < 4; ++k) toward = toward && toward_face(f, rx[k], ry[k], rz[k]) > 0.f;
    if (seen || !toward) continue;
    const float lambda = face_lambda(size, f, rx, ry, rz);
    if (std::isnan(best) || lambda < best) best = lambda;
  }
  return std::isnan(best) ? face_lambda(size, faces[0], rx, ry, rz) : best;
}

}  // namespace

void sample_cube_quad(const TextureImage& image, const Sampler& sampler, const float s_in[4], const float t_in[4],
                      const float r_in[4], float out[4][4]) {
  float rx[4], ry[4], rz[4];
  for (int i = 0; i < 4; ++i) {
    rx[i] = sane(s_in[i]);
    ry[i] = sane(t_in[i]);
    rz[i] = sane(r_in[i]);
  }
  const int max_level = static_cast<int>(image.levels.size()) - 1;
  int faces[4];
  for (int i = 0; i < 4; ++i) faces[i] = major_face(rx[i], ry[i], rz[i]);
  const LevelChoice choice = choose_levels(sampler, cube_lambda(image.levels[0].width, faces, rx, ry, rz), max_level);
  for (int i = 0; i < 4; ++i) {
    float s, t;
    face_coords(faces[i], rx[i], ry[i], rz[i], s, t);
    sample_slices(image, sampler, choice, s, t, 0.f, faces[i], out[i]);
  }
}

}  // namespace pineda::raster
