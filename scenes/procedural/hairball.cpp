// The paper's Hairball: 10,000 smooth random strands inside a ball of radius 4.6, each an open
// 3-sided tube of 48 segments (49 rings of 3 vertices, 288 triangles). At size 1 that is
// 1,470,000 vertices and 2,880,000 triangles; strands = max(1, round(10000 * size)).
// Strand i depends only on (seed, i), so smaller sizes are exact prefixes of the full scene.
#include "scenes/procedural/mesh_builder.h"
#include "scenes/procedural/params.h"
#include "scenes/procedural/procedural.h"
#include "scenes/procedural/random.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>

namespace strata::scenes {

namespace {

constexpr int kSegments = 48;
constexpr int kSides = 3;
constexpr float kBallRadius = 4.6f;
constexpr float kTubeRadius = 0.015f;
constexpr float kStep = 0.1f;  // strand length 4.8, about half the ball's diameter
// Centre lines stay inside this so the tube surface stays inside the ball.
constexpr float kCoreRadius = kBallRadius - kTubeRadius - 0.001f;
// Beyond this fraction of kCoreRadius strands are bent back inward.
constexpr float kSteerStart = 0.9f;  // lower values pile strands into a shell inside the wall

glm::vec3 in_unit_ball(Pcg32& rng) {
  for (;;) {
    const glm::vec3 p(rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f),
                      rng.uniform(-1.0f, 1.0f));
    const float l2 = glm::dot(p, p);
    if (l2 <= 1.0f && l2 > 1e-4f) return p;
  }
}

// A random walk whose turning rate itself drifts slowly, so curvature changes smoothly
// and strands curl rather than zig-zag.
void walk_strand(Pcg32& rng, std::array<glm::vec3, kSegments + 1>& pts) {
  glm::vec3 p = in_unit_ball(rng) * (0.95f * kCoreRadius);
  glm::vec3 dir = glm::normalize(in_unit_ball(rng));
  glm::vec3 turn(0.0f);
  pts[0] = p;
  for (int i = 1; i <= kSegments; ++i) {
    turn = turn * 0.8f + in_unit_ball(rng) * 0.2f;
    dir = glm::normalize(dir + turn * 0.6f);
    const float r = glm::length(p);
    const float ramp = (r / kCoreRadius - kSteerStart) / (1.0f - kSteerStart);
    if (ramp > 0.0f) {
      // Pull the outward component of the direction toward an inward target; the tangential
      // part is kept, so the strand bends along the wall instead of bouncing straight back.
      const glm::vec3 n = p / r;
      const float radial = glm::dot(dir, n);
      const float target = -0.5f * std::min(ramp, 1.0f);
      if (radial > target) dir = glm::normalize(dir + n * ((target - radial) * 0.5f));
    }
    glm::vec3 next = p + dir * kStep;
    const float nr = glm::length(next);
    if (nr > kCoreRadius) {
      next *= kCoreRadius / nr;
      // Only a strand heading exactly outward at the wall gets here; never stall in place.
      if (glm::length(next - p) < 0.1f * kStep) next = p - (p / r) * kStep;
    }
    p = next;
    pts[static_cast<std::size_t>(i)] = p;
  }
}

}  // namespace

Scene make_hairball(const ProceduralParams& params) {
  procedural::check_params("hairball", params);
  const uint64_t strands = procedural::scaled_count(10000.0, params.size, 1);

  Scene scene;
  scene.name = procedural::spec_name("hairball", params);
  scene.materials = {{"hair_dark", {0.25f, 0.16f, 0.10f}},
                     {"hair_brown", {0.55f, 0.35f, 0.20f}},
                     {"hair_blond", {0.85f, 0.70f, 0.45f}},
                     {"hair_grey", {0.60f, 0.60f, 0.62f}}};
  const auto material_count = static_cast<uint32_t>(scene.materials.size());
  scene.triangles.reserve(strands * kSegments * kSides * 2);

  std::array<glm::vec3, kSegments + 1> pts;
  for (uint64_t s = 0; s < strands; ++s) {
    Pcg32 rng = Pcg32::keyed(params.seed, s);
    const uint32_t material = rng.below(material_count);
    walk_strand(rng, pts);
    procedural::add_tube(scene.triangles, pts.data(), pts.size(), kSides, kTubeRadius,
                         kTubeRadius, material);
  }

  scene.camera.eye = {0.0f, 0.0f, 14.0f};
  scene.camera.target = {0.0f, 0.0f, 0.0f};
  scene.camera.up = {0.0f, 1.0f, 0.0f};
  scene.camera.vfov_degrees = 40.0f;  // the ball (radius 4.6) fills most of the frame
  scene.light.position = {8.0f, 10.0f, 12.0f};
  // ~17.6 units away: irradiance on the near side of the ball ~ 1000 / 17.6^2 ~ 3.
  scene.light.intensity = {1000.0f, 1000.0f, 1000.0f};
  scene.background = {0.05f, 0.05f, 0.08f};
  return scene;
}

}  // namespace strata::scenes
