// The native twin path tracer: determinism, ray accounting, and physics checked against
// closed-form answers (direct lighting of a plane, shadows, background).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "scenes/procedural/procedural.h"
#include "scenes/scene_image.h"
#include "sim/native_render.h"

namespace strata::sim {
namespace {

using kernels::kBounceRay;
using kernels::kPrimaryRay;
using kernels::kShadowRay;

constexpr float kPi = 3.14159265358979f;

// A 200x200 floor square in the plane y = 0, seen from straight above; light above it.
scenes::Scene floor_scene(bool with_occluder) {
  scenes::Scene s;
  s.name = "floor";
  s.materials.push_back({"floor", {0.5f, 0.25f, 1.0f}});
  const float r = 100.0f;
  s.triangles.push_back({{-r, 0, -r}, {r, 0, r}, {r, 0, -r}, 0});
  s.triangles.push_back({{-r, 0, -r}, {-r, 0, r}, {r, 0, r}, 0});
  if (with_occluder) {
    // A small square at height 5 under the light: its shadow on the floor is a 2x2 square
    // (the light at height 10 doubles it).
    s.triangles.push_back({{-0.5f, 5, -0.5f}, {0.5f, 5, 0.5f}, {0.5f, 5, -0.5f}, 0});
    s.triangles.push_back({{-0.5f, 5, -0.5f}, {-0.5f, 5, 0.5f}, {0.5f, 5, 0.5f}, 0});
  }
  s.camera.eye = {0, 20, 0};
  s.camera.target = {0, 0, 0};
  s.camera.up = {0, 0, -1};
  s.camera.vfov_degrees = 20.0f;
  s.light.position = {0, 10, 0};
  s.light.intensity = {100, 100, 100};
  s.background = {0.1f, 0.2f, 0.3f};
  return s;
}

RenderSettings direct_only(uint32_t size) {
  RenderSettings r;
  r.width = r.height = size;
  r.max_path_vertices = 1;
  return r;
}

TEST(NativeTwin, SameInputsGiveBitIdenticalImagesAndCounters) {
  const scenes::SceneImage img = build_scene_image(scenes::make_cornell({0.3, 1}), {}, nullptr);
  RenderSettings s;
  s.width = s.height = 24;
  s.samples_per_pixel = 2;
  const RenderResult a = render_native(img, s);
  const RenderResult b = render_native(img, s);
  ASSERT_EQ(a.image.size(), b.image.size());
  EXPECT_EQ(std::memcmp(a.image.data(), b.image.data(), a.image.size() * sizeof(kernels::Pixel)), 0);
  EXPECT_EQ(std::memcmp(&a.counters, &b.counters, sizeof a.counters), 0);
  s.seed = 2;
  const RenderResult c = render_native(img, s);
  EXPECT_NE(std::memcmp(a.image.data(), c.image.data(), a.image.size() * sizeof(kernels::Pixel)), 0);
}

TEST(NativeTwin, RaysAreAccountedForByType) {
  const scenes::SceneImage img = build_scene_image(scenes::make_cornell({0.3, 1}), {}, nullptr);
  RenderSettings s;
  s.width = s.height = 32;
  s.max_path_vertices = 5;
  const RenderResult r = render_native(img, s);
  const auto& c = r.counters;
  EXPECT_EQ(c.paths, 32u * 32u);
  EXPECT_EQ(c.rays[kPrimaryRay], 32u * 32u);
  // Every closest hit before the last vertex spawns exactly one bounce ray, so bounce rays
  // never exceed the hits, and every bounce ray comes from a hit.
  EXPECT_LE(c.rays[kBounceRay], c.hits[kPrimaryRay] + c.hits[kBounceRay]);
  EXPECT_LE(c.rays[kBounceRay], 4 * c.rays[kPrimaryRay]);
  EXPECT_GT(c.rays[kBounceRay], c.hits[kPrimaryRay]);  // the box keeps paths going
  // At most one shadow ray per closest hit (none when the light is behind the surface).
  EXPECT_LE(c.rays[kShadowRay], c.hits[kPrimaryRay] + c.hits[kBounceRay]);
  EXPECT_GT(c.rays[kShadowRay], 0u);
  EXPECT_GT(c.node_visits, c.rays[kPrimaryRay]);
}

TEST(NativeTwin, DirectLightingOfAPlaneMatchesTheClosedForm) {
  const scenes::Scene scene = floor_scene(false);
  const scenes::SceneImage img = build_scene_image(scene, {}, nullptr);
  const uint32_t n = 64;
  const RenderResult r = render_native(img, direct_only(n));
  EXPECT_EQ(r.counters.rays[kBounceRay], 0u);
  EXPECT_EQ(r.counters.hits[kPrimaryRay], n * n);
  EXPECT_EQ(r.counters.hits[kShadowRay], 0u);
  // The view covers about 7 x 7 units of floor; at the pixel centres the hit point is
  // known, and jitter inside a pixel moves it by at most half a pixel (~0.055 units).
  const float half_extent = 20.0f * std::tan(10.0f * kPi / 180.0f);
  double worst = 0;
  for (uint32_t y = 0; y < n; ++y) {
    for (uint32_t x = 0; x < n; ++x) {
      const float px = ((float(x) + 0.5f) / float(n) * 2.0f - 1.0f) * half_extent;
      const float pz = ((float(y) + 0.5f) / float(n) * 2.0f - 1.0f) * half_extent;
      const float d2 = px * px + pz * pz + 100.0f;
      // L = albedo / pi * I * cos / d^2, cos = 10 / d
      const float expected = 0.5f / kPi * 100.0f * 10.0f / (d2 * std::sqrt(d2));
      const float got = r.image[y * n + x].rgb[0];
      worst = std::max(worst, std::fabs(double(got) / expected - 1.0));
      // Channels scale with the albedo exactly as the formula says.
      EXPECT_NEAR(r.image[y * n + x].rgb[1] / got, 0.5f, 1e-5f);
      EXPECT_NEAR(r.image[y * n + x].rgb[2] / got, 2.0f, 1e-5f);
    }
  }
  EXPECT_LT(worst, 0.01) << "relative error against the closed form";
}

TEST(NativeTwin, OccluderCastsAShadowOfTheExpectedSize) {
  const scenes::SceneImage img = build_scene_image(floor_scene(true), {}, nullptr);
  const uint32_t n = 64;
  const RenderResult r = render_native(img, direct_only(n));
  const float half_extent = 20.0f * std::tan(10.0f * kPi / 180.0f);
  int dark = 0, checked = 0;
  for (uint32_t y = 0; y < n; ++y) {
    for (uint32_t x = 0; x < n; ++x) {
      const float px = ((float(x) + 0.5f) / float(n) * 2.0f - 1.0f) * half_extent;
      const float pz = ((float(y) + 0.5f) / float(n) * 2.0f - 1.0f) * half_extent;
      const float v = r.image[y * n + x].rgb[0];
      // Seen from above, the occluder (half-width 0.5 at height 5) is lit from above;
      // it hides the floor out to 0.667 (it is closer to the camera), and its shadow reaches
      // 1.0, so the ring 0.75 < max(|x|,|z|) < 0.93 is visible floor in shadow.
      const float m = std::max(std::fabs(px), std::fabs(pz));
      if (m > 0.75f && m < 0.93f) {
        ++checked;
        dark += v == 0.0f ? 1 : 0;
      } else if (m > 1.2f) {
        EXPECT_GT(v, 0.0f);
      }
    }
  }
  EXPECT_GT(checked, 20);
  EXPECT_EQ(dark, checked);
  EXPECT_GT(r.counters.hits[kShadowRay], uint64_t(checked));
}

TEST(NativeTwin, RaysThatEscapeSeeTheBackground) {
  scenes::Scene s = floor_scene(false);
  s.camera.target = {0, 40, -1};  // look up, away from the floor
  const scenes::SceneImage img = build_scene_image(s, {}, nullptr);
  const RenderResult r = render_native(img, direct_only(8));
  for (const kernels::Pixel& p : r.image) {
    EXPECT_EQ(p.rgb[0], 0.1f);
    EXPECT_EQ(p.rgb[1], 0.2f);
    EXPECT_EQ(p.rgb[2], 0.3f);
  }
  EXPECT_EQ(r.counters.hits[kPrimaryRay], 0u);
}

TEST(NativeTwin, BadSettingsAreRejected) {
  RenderSettings s;
  s.width = 0;
  EXPECT_THROW(check_render_settings(s), std::invalid_argument);
  s = {};
  s.samples_per_pixel = 0;
  EXPECT_THROW(check_render_settings(s), std::invalid_argument);
  s = {};
  s.max_path_vertices = 0;
  EXPECT_THROW(check_render_settings(s), std::invalid_argument);
}

}  // namespace
}  // namespace strata::sim
