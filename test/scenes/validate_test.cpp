// validate_triangles / require_triangles: the degenerate-triangle rule and non-finite input.
#include "scenes/validate.h"
#include "loader_fixtures.h"

#include <gtest/gtest.h>

#include <limits>

namespace strata::scenes {
namespace {

using fixtures::contains;
using fixtures::expect_scene_error;

const glm::vec3 kO{0, 0, 0}, kX{1, 0, 0}, kY{0, 1, 0};

TEST(Validate, DropsExactlyZeroAreaTrianglesAndKeepsNeedles) {
  Scene s;
  const Triangle before_first{kO, kO, kO, 0};  // not checked: before `first`
  const Triangle good{kO, kX, kY, 1};
  const Triangle repeated{kO, kX, kX, 0};
  const Triangle collinear{kO, kX, {2, 0, 0}, 0};
  const Triangle needle{kO, kX, {0.5f, 1e-20f, 0}, 2};  // tiny but nonzero area
  const Triangle sliver{{1e6f, 0, 0}, {1e6f + 0.0625f, 0, 0}, {1e6f, 1e-3f, 0}, 3};
  s.triangles = {before_first, good, repeated, collinear, needle, sliver};
  validate_triangles(s, 1, "mesh.obj");
  ASSERT_EQ(s.triangles.size(), 4u);
  EXPECT_EQ(s.triangles[0].v0, before_first.v0);
  EXPECT_EQ(s.triangles[1].material, 1u);  // order preserved
  EXPECT_EQ(s.triangles[2].material, 2u);
  EXPECT_EQ(s.triangles[3].material, 3u);
  EXPECT_EQ(s.dropped_degenerate, 2u);
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_TRUE(contains(s.warnings[0], "mesh.obj"));
  EXPECT_TRUE(contains(s.warnings[0], "2"));
}

TEST(Validate, NothingDroppedMeansNoWarning) {
  Scene s;
  s.triangles = {{kO, kX, kY, 0}};
  validate_triangles(s, 0, "a.obj");
  EXPECT_EQ(s.triangles.size(), 1u);
  EXPECT_TRUE(s.warnings.empty());
  EXPECT_EQ(s.dropped_degenerate, 0u);
}

TEST(Validate, NonFiniteCoordinateThrowsNamingSourceAndTriangle) {
  for (float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                    -std::numeric_limits<float>::infinity()}) {
    Scene s;
    s.triangles = {{kO, kX, kY, 0}, {kO, kX, kY, 0}, {kO, {1, bad, 0}, kY, 0}};
    expect_scene_error([&] { validate_triangles(s, 1, "bad.gltf"); },
                       {"bad.gltf: triangle 1 has a non-finite coordinate"});
  }
}

TEST(Validate, RequireTriangles) {
  Scene s;
  expect_scene_error([&] { require_triangles(s, "empty.json"); },
                     {"empty.json: scene has no triangles"});
  s.triangles = {{kO, kX, kY, 0}};
  EXPECT_NO_THROW(require_triangles(s, "full.json"));
}

}  // namespace
}  // namespace strata::scenes
