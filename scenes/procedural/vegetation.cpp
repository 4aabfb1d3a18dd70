// The paper's Vegetation scene: an open 60 x 60 field (x, z in [-30, 30], y up) of hills,
// grass and trees. Exact counts at size 1 (see vegetation_counts):
//   ground   100 x 100 heightfield cells             20,000 triangles
//   grass    250,000 single-triangle blades         250,000 triangles
//   trees    100 trees x 341 branches (tubes)       445,600 triangles
//   leaves   100 trees x 2,048 leaf quads           409,600 triangles
//   total                                         1,125,200 triangles
// size scales the ground's cell count (by sqrt, min 4 x 4), blades (min 64) and trees (min 1).
#include "scenes/procedural/params.h"
#include "scenes/procedural/procedural.h"
#include "scenes/procedural/random.h"
#include "scenes/procedural/terrain.h"
#include "scenes/procedural/tree.h"

#include <algorithm>
#include <cmath>

namespace strata::scenes {

namespace {

using procedural::Heightfield;

constexpr float kHalfField = 30.0f;
constexpr uint64_t kGrassKey = 2ull << 60;
constexpr uint64_t kTreeKey = 3ull << 60;
enum : uint32_t { kGround, kGrass, kBark, kLeaves };

int ground_cells(double size) {
  return std::max(4, static_cast<int>(std::lround(100.0 * std::sqrt(size))));
}

void add_grass(std::vector<Triangle>& out, const Heightfield& ground, uint64_t blades,
               uint64_t seed) {
  Pcg32 rng = Pcg32::keyed(seed, kGrassKey);
  const float edge = kHalfField - 0.2f;  // room for a blade's width and lean
  for (uint64_t i = 0; i < blades; ++i) {
    const float x = rng.uniform(-edge, edge), z = rng.uniform(-edge, edge);
    const float facing = rng.uniform(0.0f, 6.2831853f);
    const float half_width = rng.uniform(0.015f, 0.03f);
    const float height = rng.uniform(0.25f, 0.6f);
    const float lean_dir = rng.uniform(0.0f, 6.2831853f);
    const float lean = height * rng.uniform(0.0f, 0.25f);
    const float dx = std::cos(facing) * half_width, dz = std::sin(facing) * half_width;
    // Roots slightly below the surface so no blade floats on a slope.
    const glm::vec3 b0(x - dx, ground.height_at(x - dx, z - dz) - 0.02f, z - dz);
    const glm::vec3 b1(x + dx, ground.height_at(x + dx, z + dz) - 0.02f, z + dz);
    const glm::vec3 tip(x + std::cos(lean_dir) * lean, ground.height_at(x, z) + height,
                        z + std::sin(lean_dir) * lean);
    out.push_back({b0, b1, tip, kGrass});
  }
}

void add_trees(std::vector<Triangle>& out, const Heightfield& ground, uint64_t trees,
               uint64_t seed) {
  // A jittered grid, kept far enough from the edges that no branch leaves the field.
  const float limit = kHalfField - procedural::tree_reach();
  const auto cols = static_cast<uint64_t>(std::ceil(std::sqrt(static_cast<double>(trees))));
  const uint64_t rows = (trees + cols - 1) / cols;
  const float cell_x = 2.0f * limit / static_cast<float>(cols);
  const float cell_z = 2.0f * limit / static_cast<float>(rows);
  for (uint64_t i = 0; i < trees; ++i) {
    Pcg32 rng = Pcg32::keyed(seed, kTreeKey + i);
    const float cx = -limit + cell_x * (static_cast<float>(i % cols) + 0.5f);
    const float cz = -limit + cell_z * (static_cast<float>(i / cols) + 0.5f);
    const float x = std::clamp(cx + cell_x * rng.uniform(-0.35f, 0.35f), -limit, limit);
    const float z = std::clamp(cz + cell_z * rng.uniform(-0.35f, 0.35f), -limit, limit);
    // Sunk a little so the trunk's uphill side does not float.
    const glm::vec3 base(x, ground.height_at(x, z) - 0.1f, z);
    procedural::add_tree(out, base, rng, {kBark, kLeaves});
  }
}

}  // namespace

VegetationCounts vegetation_counts(const ProceduralParams& params) {
  procedural::check_params("vegetation", params);
  VegetationCounts c;
  const auto cells = static_cast<uint64_t>(ground_cells(params.size));
  c.ground_triangles = 2 * cells * cells;
  c.grass_blades = procedural::scaled_count(250000.0, params.size, 64);
  c.trees = procedural::scaled_count(100.0, params.size, 1);
  c.branches = c.trees * procedural::tree_branch_count();
  c.branch_triangles = c.trees * procedural::tree_branch_triangles();
  c.leaves = c.trees * procedural::tree_leaf_count();
  return c;
}

Scene make_vegetation(const ProceduralParams& params) {
  const VegetationCounts counts = vegetation_counts(params);  // also checks params

  Scene scene;
  scene.name = procedural::spec_name("vegetation", params);
  scene.materials = {{"ground", {0.36f, 0.25f, 0.15f}},
                     {"grass", {0.25f, 0.55f, 0.12f}},
                     {"bark", {0.30f, 0.22f, 0.16f}},
                     {"leaves", {0.18f, 0.45f, 0.10f}}};
  scene.triangles.reserve(counts.total_triangles());

  const Heightfield ground(ground_cells(params.size), kHalfField, params.seed);
  ground.add_triangles(scene.triangles, kGround);
  add_grass(scene.triangles, ground, counts.grass_blades, params.seed);
  add_trees(scene.triangles, ground, counts.trees, params.seed);

  // Over the near edge of the field, looking down across it.
  scene.camera.eye = {0.0f, 12.0f, 29.0f};
  scene.camera.target = {0.0f, 1.0f, -6.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vfov_degrees = 55.0f;
  // A far, strong point light standing in for the sun: ~440 units away, irradiance ~2.6.
  scene.light.position = {150.0f, 400.0f, 100.0f};
  scene.light.intensity = {5.2e5f, 5.0e5f, 4.5e5f};
  scene.background = {0.55f, 0.70f, 0.90f};  // sky
  return scene;
}

}  // namespace strata::scenes
