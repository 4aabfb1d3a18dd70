#include "scenes/procedural/tree.h"

#include "scenes/procedural/mesh_builder.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace strata::scenes::procedural {

namespace {

constexpr int kLevels = 5;  // trunk, three levels of branches, twigs
constexpr int kChildren = 4;
constexpr std::array<int, kLevels> kSides = {6, 5, 4, 3, 3};
constexpr std::array<int, kLevels> kSegments = {6, 4, 3, 2, 2};
constexpr int kLeavesPerTwig = 8;

constexpr float kTrunkLengthMax = 2.6f;
constexpr float kTrunkRadiusMax = 0.2f;
constexpr float kChildRatioMax = 0.62f;  // child length / parent length
constexpr float kTrunkLean = 0.12f;      // max horizontal component added per trunk segment
constexpr float kLeafLengthMax = 0.28f;

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);

struct Builder {
  std::vector<Triangle>& out;
  Pcg32& rng;
  TreeMaterials materials;

  glm::vec3 unit_ball() {
    for (;;) {
      const glm::vec3 p(rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f),
                        rng.uniform(-1.0f, 1.0f));
      const float l2 = glm::dot(p, p);
      if (l2 <= 1.0f && l2 > 1e-4f) return p;
    }
  }

  void branch(int level, const glm::vec3& start, glm::vec3 dir, float length, float radius) {
    const int segs = kSegments[static_cast<std::size_t>(level)];
    std::array<glm::vec3, 8> pts{};
    pts[0] = start;
    const float seg_len = length / static_cast<float>(segs);
    for (int s = 1; s <= segs; ++s) {
      if (level == 0) {
        // The trunk only leans a little, which keeps tree_reach() a true bound.
        dir = glm::normalize(kUp + glm::vec3(rng.uniform(-kTrunkLean, kTrunkLean), 0.0f,
                                             rng.uniform(-kTrunkLean, kTrunkLean)));
      } else {
        dir = glm::normalize(dir + unit_ball() * 0.15f + kUp * 0.05f);
      }
      pts[static_cast<std::size_t>(s)] = pts[static_cast<std::size_t>(s - 1)] + dir * seg_len;
    }
    const float tip_radius = radius * 0.6f;
    add_tube(out, pts.data(), static_cast<std::size_t>(segs + 1),
             kSides[static_cast<std::size_t>(level)], radius, tip_radius, materials.bark);

    auto point_at = [&](float t) {
      const float u = t * static_cast<float>(segs);
      const int i = std::min(static_cast<int>(u), segs - 1);
      const float f = u - static_cast<float>(i);
      const auto k = static_cast<std::size_t>(i);
      return pts[k] + (pts[k + 1] - pts[k]) * f;
    };

    if (level + 1 == kLevels) {
      for (int j = 0; j < kLeavesPerTwig; ++j) {
        const float t = (static_cast<float>(j) + rng.uniform()) / kLeavesPerTwig;
        leaf(point_at(t), dir);
      }
      return;
    }

    const float azimuth0 = rng.uniform(0.0f, 6.2831853f);
    const glm::vec3 a = any_perpendicular(dir), b = glm::cross(dir, a);
    for (int k = 0; k < kChildren; ++k) {
      // Spread children along the upper part of the parent and round it (golden angle).
      const float t = std::min(1.0f, 0.45f + 0.55f * static_cast<float>(k + 1) / kChildren -
                                          rng.uniform(0.0f, 0.1f));
      const float azimuth = azimuth0 + 2.3999632f * static_cast<float>(k) + rng.uniform(-0.3f, 0.3f);
      const float tilt = rng.uniform(0.52f, 0.96f);  // 30..55 degrees off the parent
      const glm::vec3 side = a * std::cos(azimuth) + b * std::sin(azimuth);
      glm::vec3 child = dir * std::cos(tilt) + side * std::sin(tilt);
      child = glm::normalize(child + kUp * 0.3f);
      const float child_len = length * rng.uniform(0.55f, kChildRatioMax);
      const float r_at = radius + (tip_radius - radius) * t;
      branch(level + 1, point_at(t), child, child_len, std::max(0.006f, r_at * 0.65f));
    }
  }

  void leaf(const glm::vec3& base, const glm::vec3& twig_dir) {
    const glm::vec3 dir = glm::normalize(twig_dir * 0.5f + glm::normalize(unit_ball()));
    glm::vec3 side = glm::cross(dir, unit_ball());
    side = glm::dot(side, side) < 1e-6f ? any_perpendicular(dir) : glm::normalize(side);
    const float len = rng.uniform(0.18f, kLeafLengthMax);
    const float half_width = rng.uniform(0.04f, 0.07f);
    const glm::vec3 mid = base + dir * (0.5f * len);
    const glm::vec3 tip = base + dir * len;
    const glm::vec3 left = mid + side * half_width, right = mid - side * half_width;
    out.push_back({base, left, tip, materials.leaves});
    out.push_back({base, tip, right, materials.leaves});
  }
};

uint64_t pow_children(int level) {
  uint64_t n = 1;
  for (int i = 0; i < level; ++i) n *= kChildren;
  return n;
}

}  // namespace

uint64_t tree_branch_count() {
  uint64_t n = 0;
  for (int l = 0; l < kLevels; ++l) n += pow_children(l);
  return n;
}

uint64_t tree_branch_triangles() {
  uint64_t n = 0;
  for (int l = 0; l < kLevels; ++l) {
    const auto i = static_cast<std::size_t>(l);
    n += pow_children(l) * static_cast<uint64_t>(2 * kSides[i] * kSegments[i]);
  }
  return n;
}

uint64_t tree_leaf_count() { return pow_children(kLevels - 1) * kLeavesPerTwig; }

float tree_reach() {
  // Trunk lean, plus every branch below it laid end to end, plus a leaf and the trunk radius.
  float reach = kTrunkLengthMax * kTrunkLean * 1.4143f;
  float len = kTrunkLengthMax;
  for (int l = 1; l < kLevels; ++l) {
    len *= kChildRatioMax;
    reach += len;
  }
  return reach + kLeafLengthMax + kTrunkRadiusMax;
}

void add_tree(std::vector<Triangle>& out, const glm::vec3& base, Pcg32& rng,
              TreeMaterials materials) {
  Builder builder{out, rng, materials};
  const float length = rng.uniform(2.2f, kTrunkLengthMax);
  const float radius = rng.uniform(0.14f, kTrunkRadiusMax);
  builder.branch(0, base, kUp, length, radius);
}

}  // namespace strata::scenes::procedural
