// Procedurally generated benchmark scenes from the STRaTA paper (Kopta et al., HPG 2013):
// Cornell box, Hairball and Vegetation. Generation is deterministic in (size, seed).
#pragma once

#include "scenes/scene.h"

#include <cstdint>

namespace strata::scenes {

struct ProceduralParams {
  double size = 1.0;  // fraction of the full scene, in (0, 1]; SceneError otherwise
  uint64_t seed = 1;
};

Scene make_cornell(const ProceduralParams& params);
Scene make_hairball(const ProceduralParams& params);
Scene make_vegetation(const ProceduralParams& params);

// What make_vegetation produces for the same params, so callers and tests can check the mix
// of geometry (its triangles are also tagged by material: ground, grass, bark, leaves).
struct VegetationCounts {
  uint64_t ground_triangles = 0;
  uint64_t grass_blades = 0;  // one triangle each
  uint64_t trees = 0;
  uint64_t branches = 0;  // over all trees
  uint64_t branch_triangles = 0;
  uint64_t leaves = 0;  // two triangles each
  uint64_t total_triangles() const {
    return ground_triangles + grass_blades + branch_triangles + 2 * leaves;
  }
};
VegetationCounts vegetation_counts(const ProceduralParams& params);

}  // namespace strata::scenes
