#include "scenes/procedural/procedural.h"
#include "scenes/procedural/random.h"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <algorithm>
#include <cstdio>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace strata::scenes {
namespace {

// Every triangle has finite corners, a valid material and a nonzero (float) area.
void expect_well_formed(const Scene& scene) {
  ASSERT_FALSE(scene.triangles.empty());
  uint64_t bad = 0;
  for (const Triangle& t : scene.triangles) {
    const bool finite = std::isfinite(t.v0.x) && std::isfinite(t.v0.y) && std::isfinite(t.v0.z) &&
                        std::isfinite(t.v1.x) && std::isfinite(t.v1.y) && std::isfinite(t.v1.z) &&
                        std::isfinite(t.v2.x) && std::isfinite(t.v2.y) && std::isfinite(t.v2.z);
    const float area2 = glm::length(glm::cross(t.v1 - t.v0, t.v2 - t.v0));
    if (!finite || !(area2 > 0.0f) || t.material >= scene.materials.size()) ++bad;
  }
  EXPECT_EQ(bad, 0u) << scene.name;
}

bool same_bits(const std::vector<Triangle>& a, const std::vector<Triangle>& b) {
  static_assert(sizeof(Triangle) == 9 * sizeof(float) + sizeof(uint32_t), "no padding");
  return a.size() == b.size() &&
         std::memcmp(a.data(), b.data(), a.size() * sizeof(Triangle)) == 0;
}

std::vector<uint64_t> count_by_material(const Scene& scene) {
  std::vector<uint64_t> n(scene.materials.size(), 0);
  for (const Triangle& t : scene.triangles) ++n.at(t.material);
  return n;
}

uint32_t material_index(const Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    if (scene.materials[i].name == name) return static_cast<uint32_t>(i);
  }
  ADD_FAILURE() << "no material " << name << " in " << scene.name;
  return 0;
}

float max_radius(const Scene& scene) {
  float r = 0.0f;
  for (const Triangle& t : scene.triangles) {
    r = std::max({r, glm::length(t.v0), glm::length(t.v1), glm::length(t.v2)});
  }
  return r;
}

// Height of the ground mesh under (x, z), found through the triangles' own grid cells.
class GroundGrid {
 public:
  GroundGrid(const Scene& scene, uint32_t material) {
    for (const Triangle& t : scene.triangles) {
      if (t.material == material) tris_.push_back(&t);
    }
    cells_ = static_cast<int>(std::lround(std::sqrt(static_cast<double>(tris_.size()) / 2.0)));
    EXPECT_EQ(2u * cells_ * cells_, tris_.size());
    buckets_.resize(static_cast<std::size_t>(cells_ * cells_));
    for (const Triangle* t : tris_) {
      const glm::vec3 c = (t->v0 + t->v1 + t->v2) / 3.0f;
      buckets_[index(c.x, c.z)].push_back(t);
    }
  }

  float y(float x, float z) const {
    for (const Triangle* t : buckets_[index(x, z)]) {
      const glm::vec2 a(t->v0.x, t->v0.z), b(t->v1.x, t->v1.z), c(t->v2.x, t->v2.z);
      const float d = (b.y - c.y) * (a.x - c.x) + (c.x - b.x) * (a.y - c.y);
      const float w0 = ((b.y - c.y) * (x - c.x) + (c.x - b.x) * (z - c.y)) / d;
      const float w1 = ((c.y - a.y) * (x - c.x) + (a.x - c.x) * (z - c.y)) / d;
      const float w2 = 1.0f - w0 - w1;
      if (w0 >= -1e-4f && w1 >= -1e-4f && w2 >= -1e-4f) {
        return w0 * t->v0.y + w1 * t->v1.y + w2 * t->v2.y;
      }
    }
    ADD_FAILURE() << "no ground under " << x << ", " << z;
    return 0.0f;
  }

 private:
  std::size_t index(float x, float z) const {
    auto cell = [&](float v) {
      return std::clamp(static_cast<int>((v + 30.0f) / 60.0f * static_cast<float>(cells_)), 0,
                        cells_ - 1);
    };
    return static_cast<std::size_t>(cell(z) * cells_ + cell(x));
  }

  std::vector<const Triangle*> tris_;
  std::vector<std::vector<const Triangle*>> buckets_;
  int cells_ = 0;
};

// Trees counted from the geometry alone: bark vertices below the ground are trunk bases;
// clusters of them further apart than a trunk's width are separate trees.
uint64_t count_trunks(const Scene& scene) {
  const GroundGrid ground(scene, material_index(scene, "ground"));
  const uint32_t bark = material_index(scene, "bark");
  std::vector<glm::vec2> bases;
  for (const Triangle& t : scene.triangles) {
    if (t.material != bark) continue;
    for (const glm::vec3& v : {t.v0, t.v1, t.v2}) {
      if (v.y < ground.y(v.x, v.z) - 0.02f) bases.emplace_back(v.x, v.z);
    }
  }
  std::vector<glm::vec2> trunks;
  for (const glm::vec2& p : bases) {
    bool known = false;
    for (const glm::vec2& q : trunks) known = known || glm::length(p - q) < 0.6f;
    if (!known) trunks.push_back(p);
  }
  return trunks.size();
}

// --- RNG ---------------------------------------------------------------------------------

TEST(ProceduralRandom, MatchesReferenceVectors) {
  // splitmix64.c (Vigna) from state 0, and pcg32-demo's pcg32_srandom(42, 54).
  uint64_t sm = 0;
  EXPECT_EQ(splitmix64(sm), 0xE220A8397B1DCDAFull);
  Pcg32 pcg(42u, 54u);
  const uint32_t expected[] = {0xa15c02b7, 0x7b47f409, 0xba1d3330,
                               0x83d2f293, 0xbfa4784b, 0xcbed606e};
  for (uint32_t e : expected) EXPECT_EQ(pcg.next_u32(), e);
}

TEST(ProceduralRandom, UniformStaysInRangeAndBelowIsUnbiasedEnough) {
  Pcg32 rng = Pcg32::keyed(7, 3);
  double sum = 0.0;
  int buckets[5] = {};
  for (int i = 0; i < 100000; ++i) {
    const float u = rng.uniform();
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    sum += u;
    ++buckets[rng.below(5)];
  }
  EXPECT_NEAR(sum / 100000.0, 0.5, 0.01);
  for (int b : buckets) EXPECT_NEAR(b, 20000, 800);
  EXPECT_NE(Pcg32::keyed(7, 3).next_u32(), Pcg32::keyed(7, 4).next_u32());
  EXPECT_NE(Pcg32::keyed(7, 3).next_u32(), Pcg32::keyed(8, 3).next_u32());
}

// --- Parameters ----------------------------------------------------------------------------

TEST(ProceduralParams, BadSizeThrowsSceneErrorNamingSceneAndParameter) {
  const double bad[] = {0.0, -0.5, 1.0000001, 2.0, std::numeric_limits<double>::quiet_NaN(),
                        std::numeric_limits<double>::infinity()};
  for (double size : bad) {
    for (auto make : {&make_cornell, &make_hairball, &make_vegetation}) {
      try {
        make(ProceduralParams{size, 1});
        ADD_FAILURE() << "no error for size " << size;
      } catch (const SceneError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("size"), std::string::npos) << msg;
        EXPECT_TRUE(msg.rfind("cornell", 0) == 0 || msg.rfind("hairball", 0) == 0 ||
                    msg.rfind("vegetation", 0) == 0)
            << msg;
      }
    }
  }
  EXPECT_THROW(vegetation_counts(ProceduralParams{0.0, 1}), SceneError);
}

// --- Cornell box --------------------------------------------------------------------------

TEST(ProceduralCornell, FullSizeBoxHasColouredWallsAndBlocks) {
  const Scene scene = make_cornell({});
  EXPECT_EQ(scene.triangles.size(), 3200u);
  expect_well_formed(scene);
  const Bounds b = scene.bounds();
  EXPECT_NEAR(b.min.x, -1.0f, 1e-5f);
  EXPECT_NEAR(b.max.x, 1.0f, 1e-5f);
  EXPECT_NEAR(b.min.y, 0.0f, 1e-5f);
  EXPECT_NEAR(b.max.y, 2.0f, 1e-5f);
  EXPECT_NEAR(b.min.z, -1.0f, 1e-5f);
  EXPECT_NEAR(b.max.z, 1.0f, 1e-5f);

  const uint32_t red = material_index(scene, "red"), green = material_index(scene, "green");
  EXPECT_GT(scene.materials[red].albedo.r, 3.0f * scene.materials[red].albedo.g);
  EXPECT_GT(scene.materials[green].albedo.g, 2.0f * scene.materials[green].albedo.r);
  // Red wall all at x = -1 (left of the camera), green at x = +1.
  for (const Triangle& t : scene.triangles) {
    if (t.material == red) {
      EXPECT_FLOAT_EQ(t.v0.x + t.v1.x + t.v2.x, -3.0f);
    }
    if (t.material == green) {
      EXPECT_FLOAT_EQ(t.v0.x + t.v1.x + t.v2.x, 3.0f);
    }
  }
  // Two blocks inside the box: the tall one reaches ~330/555*2 = 1.19, the short ~0.59.
  float tall = 0.0f;
  uint64_t block_tris = 0;
  for (const Triangle& t : scene.triangles) {
    const glm::vec3 c = (t.v0 + t.v1 + t.v2) / 3.0f;
    if (std::abs(c.x) < 0.99f && std::abs(c.z) < 0.99f && c.y > 0.001f && c.y < 1.99f) {
      ++block_tris;
      tall = std::max({tall, t.v0.y, t.v1.y, t.v2.y});
    }
  }
  EXPECT_EQ(block_tris, 2u * 5u * 2u * 100u);
  EXPECT_NEAR(tall, 330.0f * 2.0f / 555.0f, 1e-4f);

  EXPECT_GT(scene.camera.eye.z, 1.0f);  // in front of the open side
  EXPECT_GE(scene.light.position.y, 1.5f);  // in the upper part of the box, below the ceiling
  EXPECT_LT(scene.light.position.y, 2.0f);
  EXPECT_EQ(scene.background, glm::vec3(0.0f));
}

TEST(ProceduralCornell, TinySizeGivesBasicBox) {
  const Scene scene = make_cornell({0.001, 1});
  EXPECT_EQ(scene.triangles.size(), 32u);
  expect_well_formed(scene);
  EXPECT_EQ(scene.triangles.size(), make_cornell({0.001, 99}).triangles.size());
}

// --- Hairball ----------------------------------------------------------------------------

TEST(ProceduralHairball, SmallSizeStrandsAreOpenTubesInsideTheBall) {
  const Scene scene = make_hairball({0.01, 1});
  ASSERT_EQ(scene.triangles.size(), 100u * 288u);
  expect_well_formed(scene);
  // 100 strands x 49 rings x 3 vertices, none shared between strands or rings.
  std::set<std::tuple<float, float, float>> vertices;
  for (const Triangle& t : scene.triangles) {
    for (const glm::vec3& v : {t.v0, t.v1, t.v2}) vertices.emplace(v.x, v.y, v.z);
  }
  EXPECT_EQ(vertices.size(), 100u * 49u * 3u);
  const float r = max_radius(scene);
  EXPECT_LE(r, 4.6f * 1.01f);
  EXPECT_GT(r, 4.0f);  // strands reach the outer shell, the ball is filled
  EXPECT_GE(scene.materials.size(), 3u);
  EXPECT_GT(glm::length(scene.camera.eye), 4.6f * 1.01f);
  EXPECT_GT(glm::length(scene.light.position), 4.6f * 1.01f);
}

TEST(ProceduralHairball, StrandsAreSmooth) {
  // Ring centres: average of each ring's 3 vertices (the first triangle of each side pair).
  const Scene scene = make_hairball({0.001, 5});
  ASSERT_EQ(scene.triangles.size(), 10u * 288u);
  float worst_cos = 1.0f;
  for (std::size_t s = 0; s < 10; ++s) {
    std::vector<glm::vec3> centres;
    const Triangle* strand = &scene.triangles[s * 288];
    for (int seg = 0; seg < 48; ++seg) {
      const Triangle* q = strand + seg * 6;  // 3 sides x 2 triangles; v0 of 0,2,4 = ring seg
      centres.push_back((q[0].v0 + q[2].v0 + q[4].v0) / 3.0f);
    }
    for (std::size_t i = 2; i < centres.size(); ++i) {
      const glm::vec3 a = glm::normalize(centres[i - 1] - centres[i - 2]);
      const glm::vec3 b = glm::normalize(centres[i] - centres[i - 1]);
      worst_cos = std::min(worst_cos, glm::dot(a, b));
    }
  }
  EXPECT_GT(worst_cos, std::cos(60.0f * 3.14159265f / 180.0f));  // no kinks
}

TEST(ProceduralHairball, FullSizeCountsBoundsAndPrefix) {
  const Scene scene = make_hairball({});  // build time: scripts/bench-scenes
  ASSERT_EQ(scene.triangles.size(), 2880000u);
  EXPECT_LE(max_radius(scene), 4.6f * 1.01f);
  expect_well_formed(scene);
  std::vector<uint64_t> per_material = count_by_material(scene);
  for (uint64_t n : per_material) EXPECT_GT(n, 2880000u / 10u);  // every colour used
  // Strand i depends only on (seed, i): the 100-strand scene is a prefix of the full one.
  const Scene small = make_hairball({0.01, 1});
  EXPECT_EQ(std::memcmp(small.triangles.data(), scene.triangles.data(),
                        small.triangles.size() * sizeof(Triangle)),
            0);
}

TEST(ProceduralHairball, DeterministicPerSeed) {
  const Scene a = make_hairball({0.02, 42});
  const Scene b = make_hairball({0.02, 42});
  const Scene c = make_hairball({0.02, 43});
  EXPECT_TRUE(same_bits(a.triangles, b.triangles));
  ASSERT_EQ(a.triangles.size(), c.triangles.size());
  EXPECT_FALSE(same_bits(a.triangles, c.triangles));
  EXPECT_EQ(a.name, b.name);
  EXPECT_NE(a.name, c.name);
}

// --- Vegetation --------------------------------------------------------------------------

void expect_inside_field(const Scene& scene) {
  const Bounds b = scene.bounds();
  EXPECT_GE(b.min.x, -30.0f);
  EXPECT_LE(b.max.x, 30.0f);
  EXPECT_GE(b.min.z, -30.0f);
  EXPECT_LE(b.max.z, 30.0f);
  EXPECT_GT(b.min.y, -5.0f);
  EXPECT_LT(b.max.y, 15.0f);
}

TEST(ProceduralVegetation, FullSizeMixOfGroundGrassAndTrees) {
  const Scene scene = make_vegetation({});  // build time: scripts/bench-scenes

  const VegetationCounts c = vegetation_counts({});
  EXPECT_EQ(scene.triangles.size(), c.total_triangles());
  EXPECT_GE(scene.triangles.size(), 1000000u);
  EXPECT_LE(scene.triangles.size(), 1200000u);
  EXPECT_EQ(c.trees, 100u);

  const std::vector<uint64_t> n = count_by_material(scene);
  const uint64_t ground = n[material_index(scene, "ground")];
  const uint64_t grass = n[material_index(scene, "grass")];
  const uint64_t bark = n[material_index(scene, "bark")];
  const uint64_t leaves = n[material_index(scene, "leaves")];
  EXPECT_EQ(ground, c.ground_triangles);
  EXPECT_EQ(grass, c.grass_blades);
  EXPECT_EQ(bark, c.branch_triangles);
  EXPECT_EQ(leaves, 2 * c.leaves);
  EXPECT_NEAR(static_cast<double>(ground), 20000.0, 2000.0);
  EXPECT_NEAR(static_cast<double>(grass), 250000.0, 10000.0);
  EXPECT_NEAR(static_cast<double>(bark + leaves), 830000.0, 60000.0);
  expect_inside_field(scene);
  expect_well_formed(scene);

  EXPECT_EQ(count_trunks(scene), 100u);
  const Bounds b = scene.bounds();
  EXPECT_LT(b.min.x, -25.0f);  // the ground spans the whole field
  EXPECT_GT(scene.camera.eye.y, b.max.y * 0.5f);
  EXPECT_GT(scene.light.position.y, 100.0f);
}

TEST(ProceduralVegetation, GrassStandsOnTheGround) {
  const Scene scene = make_vegetation({0.01, 3});
  const uint32_t grass = material_index(scene, "grass");
  const GroundGrid ground(scene, material_index(scene, "ground"));
  uint64_t blades = 0;
  for (const Triangle& t : scene.triangles) {
    if (t.material != grass) continue;
    ++blades;
    // Roots 2 cm under the surface, tip well above them.
    EXPECT_NEAR(t.v0.y, ground.y(t.v0.x, t.v0.z) - 0.02f, 1e-3f);
    EXPECT_NEAR(t.v1.y, ground.y(t.v1.x, t.v1.z) - 0.02f, 1e-3f);
    EXPECT_GT(t.v2.y, std::max(t.v0.y, t.v1.y) + 0.2f);
  }
  EXPECT_EQ(blades, 2500u);
}

TEST(ProceduralVegetation, TinySizeStillHasATreeGrassAndGround) {
  const Scene scene = make_vegetation({1e-6, 1});
  const VegetationCounts c = vegetation_counts({1e-6, 1});
  EXPECT_EQ(c.trees, 1u);
  EXPECT_GE(c.grass_blades, 1u);
  EXPECT_GE(c.ground_triangles, 2u);
  EXPECT_EQ(scene.triangles.size(), c.total_triangles());
  const std::vector<uint64_t> n = count_by_material(scene);
  for (uint64_t k : n) EXPECT_GT(k, 0u);
  expect_well_formed(scene);
  expect_inside_field(scene);
}

TEST(ProceduralVegetation, SmallSizeWellFormedAndScaled) {
  const Scene scene = make_vegetation({0.05, 9});
  const VegetationCounts c = vegetation_counts({0.05, 9});
  EXPECT_EQ(c.trees, 5u);
  EXPECT_EQ(c.grass_blades, 12500u);
  EXPECT_EQ(scene.triangles.size(), c.total_triangles());
  expect_well_formed(scene);
  expect_inside_field(scene);
}

TEST(ProceduralVegetation, DeterministicPerSeed) {
  const Scene a = make_vegetation({0.02, 42});
  const Scene b = make_vegetation({0.02, 42});
  const Scene c = make_vegetation({0.02, 43});
  EXPECT_TRUE(same_bits(a.triangles, b.triangles));
  ASSERT_EQ(a.triangles.size(), c.triangles.size());
  EXPECT_FALSE(same_bits(a.triangles, c.triangles));
}

TEST(ProceduralCornell, Deterministic) {
  EXPECT_TRUE(same_bits(make_cornell({0.3, 1}).triangles, make_cornell({0.3, 1}).triangles));
}

}  // namespace
}  // namespace strata::scenes
