// The fused pipelines as the ISA presents them, over firmware/common/intersect.h.
#include "model/iss/pipeline_reference.h"

#include <gtest/gtest.h>

#include <limits>

namespace strata::iss {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

strata_pipe_ray make_ray(float ox, float oy, float oz, float dx, float dy, float dz, float tmin = 0.0f,
                         float tmax = kInf) {
  return {{ox, oy, oz}, tmin, {dx, dy, dz}, tmax, {1.0f / dx, 1.0f / dy, 1.0f / dz}, 0.0f};
}

TEST(IssPipeline, BoxEntryDistanceAndMisses) {
  const strata_pipe_box box = {{-1, -1, -1}, {1, 1, 1}};
  BoxTestResult r = box_test(make_ray(0, 0, -5, 0, 0, 1), box);
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.t_entry, 4.0f);
  r = box_test(make_ray(0, 0, 0, 0, 0, 1), box);  // inside: entry clamps to tmin
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.t_entry, 0.0f);
  r = box_test(make_ray(0, 0, -5, 0, 0, -1), box);  // behind the origin
  EXPECT_FALSE(r.hit);
  EXPECT_EQ(r.t_entry, kInf);  // the ISA reports +inf on a miss
  EXPECT_FALSE(box_test(make_ray(0, 0, -5, 0, 0, 1, 0.0f, 3.0f), box).hit);  // beyond tmax
  EXPECT_FALSE(box_test(make_ray(3, 0, -5, 0, 0, 1), box).hit);  // parallel, outside the slab
  r = box_test(make_ray(1, 0, -5, 0, 0, 1), box);  // inside a slab plane: the closed box is hit
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.t_entry, 4.0f);
}

TEST(IssPipeline, TriangleHitThenDivide) {
  const strata_pipe_triangle tri = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  const TrianglePartial none{};
  TriangleTestResult r = triangle_test(make_ray(0.5f, 0.5f, 2, 0, 0, -1), tri, none);
  ASSERT_TRUE(r.hit);
  TriangleHit h = triangle_divide(r.partial);
  EXPECT_EQ(h.t, 2.0f);
  EXPECT_EQ(h.b1, 0.25f);
  EXPECT_EQ(h.b2, 0.25f);
  const strata_pipe_triangle flipped = {{0, 0, 0}, {0, 2, 0}, {2, 0, 0}};  // both windings hit
  r = triangle_test(make_ray(0.5f, 0.5f, 2, 0, 0, -1), flipped, none);
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(triangle_divide(r.partial).t, 2.0f);
  EXPECT_FALSE(triangle_test(make_ray(1.5f, 1.5f, 2, 0, 0, -1), tri, none).hit);  // outside an edge
  EXPECT_FALSE(triangle_test(make_ray(0.5f, 0.5f, 2, 0, 0, 1), tri, none).hit);   // pointing away
  EXPECT_FALSE(triangle_test(make_ray(-1, 0.5f, 0, 1, 0, 0), tri, none).hit);     // in the plane
  // The division-free stage ignores tmin/tmax: the firmware compares the divided t.
  EXPECT_TRUE(triangle_test(make_ray(0.5f, 0.5f, 2, 0, 0, -1, 0.0f, 1.0f), tri, none).hit);
}

TEST(IssPipeline, AMissKeepsThePreviousPartial) {
  const strata_pipe_triangle tri = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
  const TriangleTestResult hit = triangle_test(make_ray(0.5f, 0.5f, 2, 0, 0, -1), tri, TrianglePartial{});
  const TriangleTestResult miss = triangle_test(make_ray(5, 5, 2, 0, 0, -1), tri, hit.partial);
  EXPECT_FALSE(miss.hit);
  EXPECT_EQ(triangle_divide(miss.partial).t, 2.0f);
}

}  // namespace
}  // namespace strata::iss
