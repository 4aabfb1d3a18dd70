// One tree of the Vegetation scene: a trunk that branches 4 ways per level down to twigs,
// all thin tapered tubes, with diamond-shaped leaf quads on the twigs. The topology is fixed
// (only lengths, angles and bends are random), so every tree has the same triangle count.
#pragma once

#include "scenes/procedural/random.h"
#include "scenes/scene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace strata::scenes::procedural {

struct TreeMaterials {
  uint32_t bark;
  uint32_t leaves;
};

uint64_t tree_branch_count();     // per tree
uint64_t tree_branch_triangles();  // per tree
uint64_t tree_leaf_count();        // per tree, 2 triangles each

// Upper bound on the horizontal distance of any tree vertex from its base point.
float tree_reach();

void add_tree(std::vector<Triangle>& out, const glm::vec3& base, Pcg32& rng,
              TreeMaterials materials);

}  // namespace strata::scenes::procedural
