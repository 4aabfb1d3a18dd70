// The classic Cornell box (Cornell Program of Computer Graphics measurements), scaled so the
// box is x in [-1,1], y in [0,2], z in [-1,1] with the open side at z = +1 facing the camera.
// size only sets the tessellation: every quad becomes n x n cells, n = round(10 * sqrt(size)),
// giving 16 quads * 2 * n^2 = 3,200 triangles at size 1 and the bare 32 at tiny sizes.
#include "scenes/procedural/mesh_builder.h"
#include "scenes/procedural/params.h"
#include "scenes/procedural/procedural.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace strata::scenes {

namespace {

using procedural::add_grid_quad;

enum : uint32_t { kWhite, kRed, kGreen, kLamp };

// Original data has +x to the viewer's left and +z into the box; mirror both so the camera
// looks down -z in a right-handed frame (tall block back left, short block front right).
glm::vec3 from_cornell(float x, float y, float z) {
  constexpr float s = 2.0f / 555.0f;
  return {(278.0f - x) * s, y * s, (279.6f - z) * s};
}

// A block given by its four top corners (in order); sides drop straight to the floor. The
// bottom face is omitted because it would lie in the floor plane.
void add_block(std::vector<Triangle>& out, const std::array<glm::vec3, 4>& top, int n) {
  glm::vec3 centre(0.0f);
  for (const glm::vec3& p : top) centre += p * 0.25f;
  centre.y *= 0.5f;
  add_grid_quad(out, top[0], top[1], top[2], top[3], n, {0, 1, 0}, kWhite);
  for (int k = 0; k < 4; ++k) {
    const glm::vec3 a = top[k], b = top[(k + 1) % 4];
    const glm::vec3 b0(b.x, 0.0f, b.z), a0(a.x, 0.0f, a.z);
    const glm::vec3 mid = (a + b0) * 0.5f;
    add_grid_quad(out, a, b, b0, a0, n, mid - centre, kWhite);
  }
}

}  // namespace

Scene make_cornell(const ProceduralParams& params) {
  procedural::check_params("cornell", params);
  const int n = std::max(1, static_cast<int>(std::lround(10.0 * std::sqrt(params.size))));

  Scene scene;
  scene.name = procedural::spec_name("cornell", params);
  // Albedos of the usual RGB rendition of the measured spectra.
  scene.materials = {{"white", {0.725f, 0.71f, 0.68f}},
                     {"red", {0.63f, 0.065f, 0.05f}},
                     {"green", {0.14f, 0.45f, 0.091f}},
                     {"lamp", {0.78f, 0.78f, 0.78f}}};
  scene.triangles.reserve(static_cast<std::size_t>(32 * n * n));

  auto& tris = scene.triangles;
  const float f = 1.0f;  // open front
  add_grid_quad(tris, {-1, 0, f}, {1, 0, f}, {1, 0, -1}, {-1, 0, -1}, n, {0, 1, 0}, kWhite);
  add_grid_quad(tris, {-1, 2, f}, {1, 2, f}, {1, 2, -1}, {-1, 2, -1}, n, {0, -1, 0}, kWhite);
  add_grid_quad(tris, {-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1}, n, {0, 0, 1}, kWhite);
  add_grid_quad(tris, {-1, 0, f}, {-1, 0, -1}, {-1, 2, -1}, {-1, 2, f}, n, {1, 0, 0}, kRed);
  add_grid_quad(tris, {1, 0, f}, {1, 0, -1}, {1, 2, -1}, {1, 2, f}, n, {-1, 0, 0}, kGreen);
  // The lamp opening of the original (130 x 105 units), as a panel just under the ceiling so
  // the light source is visible in the image; the point light hangs below it.
  const float lx = 65.0f * 2.0f / 555.0f, lz = 52.5f * 2.0f / 555.0f, ly = 1.999f;
  add_grid_quad(tris, {-lx, ly, lz}, {lx, ly, lz}, {lx, ly, -lz}, {-lx, ly, -lz}, n, {0, -1, 0},
                kLamp);

  add_block(tris,
            {from_cornell(130, 165, 65), from_cornell(82, 165, 225),
             from_cornell(240, 165, 272), from_cornell(290, 165, 114)},
            n);
  add_block(tris,
            {from_cornell(423, 330, 247), from_cornell(265, 330, 296),
             from_cornell(314, 330, 456), from_cornell(472, 330, 406)},
            n);

  // The original camera: 800 units in front of the opening, 35 mm lens on 25 mm film.
  scene.camera.eye = from_cornell(278, 273, -800);
  scene.camera.target = {scene.camera.eye.x, scene.camera.eye.y, 0.0f};
  scene.camera.up = {0, 1, 0};
  scene.camera.vfov_degrees = 39.3f;
  // Half a unit below the ceiling: closer, the ceiling around it would be lit ~100x brighter
  // than the floor and indirect paths through it would show as fireflies.
  scene.light.position = {0.0f, 1.5f, 0.0f};
  scene.light.intensity = {5.0f, 4.4f, 3.3f};  // warm, like the measured lamp
  scene.background = {0.0f, 0.0f, 0.0f};
  return scene;
}

}  // namespace strata::scenes
