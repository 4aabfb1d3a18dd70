// Shared helpers for the numerics suite: closed test meshes (icosphere, 12-triangle box,
// high-valence double cone), brute-force closest hit with the production triangle test,
// scene images of a mesh, and a double-precision reference ray-triangle test.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "firmware/common/float_bits.h"
#include "firmware/common/intersect.h"
#include "firmware/common/traverse.h"
#include "scenes/procedural/random.h"
#include "scenes/scene.h"
#include "scenes/scene_image.h"

namespace strata::numerics {

using scenes::Pcg32;

// Rounds a double to float, for real. GCC 12's C++ front end only has
// -fexcess-precision=fast, under which -O2/-O3 code was seen to hand the *unrounded* double to
// a later widening of float(x) back to double (test references then disagree with the
// float inputs they are meant to describe). The volatile store forces the rounding. The
// production arithmetic is all-float and has no such double -> float -> double chain.
inline float round_f(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}

// Uniform direction on the unit sphere, normalised in double then rounded.
inline Vec3f random_unit(Pcg32& rng) {
  for (;;) {
    const double x = 2.0 * rng.uniform() - 1.0, y = 2.0 * rng.uniform() - 1.0,
                 z = 2.0 * rng.uniform() - 1.0;
    const double l = std::sqrt(x * x + y * y + z * z);
    if (l > 1e-3 && l <= 1.0) return {round_f(x / l), round_f(y / l), round_f(z / l)};
  }
}

inline Vec3f to_vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }
inline glm::vec3 to_glm(Vec3f v) { return {v.x, v.y, v.z}; }

// An indexed triangle mesh: every vertex is stored once, so triangles sharing it share its
// bits exactly (the premise of watertightness). Faces are counter-clockwise seen from outside.
struct Mesh {
  std::vector<Vec3f> v;
  std::vector<std::array<uint32_t, 3>> f;

  // Vertices v * scale + offset, rounded once per vertex.
  Mesh transformed(double scale, Vec3f offset) const {
    Mesh m = *this;
    for (Vec3f& p : m.v)
      p = {round_f(double(p.x) * scale + double(offset.x)), round_f(double(p.y) * scale + double(offset.y)),
           round_f(double(p.z) * scale + double(offset.z))};
    return m;
  }
  std::vector<scenes::Triangle> triangles() const {
    std::vector<scenes::Triangle> out;
    for (const auto& t : f) out.push_back({to_glm(v[t[0]]), to_glm(v[t[1]]), to_glm(v[t[2]]), 0});
    return out;
  }
};

// Icosahedron subdivided `levels` times, vertices projected to the unit sphere (in double).
inline Mesh icosphere(int levels) {
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<std::array<double, 3>> p = {{-1, g, 0}, {1, g, 0},  {-1, -g, 0}, {1, -g, 0},
                                          {0, -1, g}, {0, 1, g},  {0, -1, -g}, {0, 1, -g},
                                          {g, 0, -1}, {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  std::vector<std::array<uint32_t, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                            {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                            {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                            {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  auto normalise = [](std::array<double, 3> a) {
    const double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    return std::array<double, 3>{a[0] / l, a[1] / l, a[2] / l};
  };
  for (auto& q : p) q = normalise(q);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> mid;
    auto midpoint = [&](uint32_t a, uint32_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      p.push_back(normalise({p[a][0] + p[b][0], p[a][1] + p[b][1], p[a][2] + p[b][2]}));
      const uint32_t i = uint32_t(p.size() - 1);
      mid[key] = i;
      return i;
    };
    std::vector<std::array<uint32_t, 3>> next;
    for (const auto& t : f) {
      const uint32_t ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      next.push_back({t[0], ab, ca});
      next.push_back({t[1], bc, ab});
      next.push_back({t[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    f = next;
  }
  Mesh m;
  for (const auto& q : p) m.v.push_back({round_f(q[0]), round_f(q[1]), round_f(q[2])});
  m.f = f;
  return m;
}

// The cube [-1, 1]^3 as 12 triangles (two per face), outward facing.
inline Mesh box12() {
  Mesh m;
  for (int i = 0; i < 8; ++i)
    m.v.push_back({(i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f});
  // Each face as a quad a b c d, counter-clockwise from outside, split along a-c.
  const uint32_t quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& q : quads) {
    m.f.push_back({q[0], q[1], q[2]});
    m.f.push_back({q[0], q[2], q[3]});
  }
  return m;
}

// A closed double cone: apex (0, 0, 1), apex (0, 0, -1), and a ring of n vertices of
// radius 1 in z = 0. Each apex has valence n, so 2n triangles meet at the two apices.
inline Mesh double_cone(uint32_t n) {
  Mesh m;
  m.v.push_back({0.0f, 0.0f, 1.0f});
  m.v.push_back({0.0f, 0.0f, -1.0f});
  const double kTwoPi = 6.283185307179586476925;
  for (uint32_t i = 0; i < n; ++i) {
    const double a = kTwoPi * double(i) / double(n);
    m.v.push_back({round_f(std::cos(a)), round_f(std::sin(a)), 0.0f});
  }
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t r0 = 2 + i, r1 = 2 + (i + 1) % n;
    m.f.push_back({0, r0, r1});
    m.f.push_back({1, r1, r0});
  }
  return m;
}

inline scenes::Scene mesh_scene(const Mesh& m, const std::string& name) {
  scenes::Scene s;
  s.name = name;
  s.materials.push_back({"grey", {0.5f, 0.5f, 0.5f}});
  s.triangles = m.triangles();
  return s;
}

// Closest hit over all triangles by the traversal's rule (tmin < t < tmax, first of equals).
inline ClosestHit brute_force(const std::vector<scenes::Triangle>& tris, const TraceRay& ray) {
  ClosestHit best{};
  best.t = ray.tmax;
  for (uint32_t i = 0; i < tris.size(); ++i) {
    const scenes::Triangle& t = tris[i];
    TrianglePartial p;
    if (!triangle_hit_test(to_vec(t.v0), to_vec(t.v1), to_vec(t.v2), ray.origin, ray.dir, &p)) continue;
    const TriangleHit h = triangle_finish(p);
    if (h.t > ray.tmin && h.t < best.t) {
      best.hit = true;
      best.t = h.t;
      best.b1 = h.b1;
      best.b2 = h.b2;
      best.primitive = i;
      best.material = t.material;
    }
  }
  return best;
}

inline ClosestHit trace(const scenes::SceneImage& img, const TraceRay& ray) {
  NullObserver obs;
  return trace_closest(img, img.header().root_node, ray, obs);
}

// The traversal may cull a box whose rounded entry distance lands just past the current
// closest hit, so at a shared edge or vertex it can return the other of two triangles whose
// hit points differ by less than the resolution of the coordinates (a hit on a sliver
// triangle's edge is only known to a few ulps of the coordinates). Such a pair is one
// surface point: the points o + t d differ by at most 2^-20 (8 ulps) of the largest
// coordinate magnitude involved. Anything farther would be a real miss of the closest hit.
inline bool same_point(Vec3f o, Vec3f d, float t_a, float t_b) {
  const double dmax = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
  const double omax = std::max({std::fabs(o.x), std::fabs(o.y), std::fabs(o.z)});
  const double reach = omax + dmax * std::max(double(t_a), double(t_b));
  return std::fabs(double(t_a) - double(t_b)) * dmax <= 0x1p-20 * reach;
}

// Double-precision reference (Möller-Trumbore on the float inputs): t and barycentrics of
// the line's intersection with the triangle's plane, with no inside test applied.
struct RefHit {
  bool valid;  // the line is not parallel to the plane
  double t, b0, b1, b2;
};
inline RefHit reference_hit(Vec3f v0, Vec3f v1, Vec3f v2, Vec3f o, Vec3f d) {
  const double e1[3] = {double(v1.x) - v0.x, double(v1.y) - v0.y, double(v1.z) - v0.z};
  const double e2[3] = {double(v2.x) - v0.x, double(v2.y) - v0.y, double(v2.z) - v0.z};
  const double dd[3] = {d.x, d.y, d.z};
  const double s[3] = {double(o.x) - v0.x, double(o.y) - v0.y, double(o.z) - v0.z};
  auto cross = [](const double* a, const double* b, double* c) {
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
  };
  auto dot = [](const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  double pv[3], qv[3];
  cross(dd, e2, pv);
  const double det = dot(e1, pv);
  if (det == 0.0) return {false, 0, 0, 0, 0};
  const double b1 = dot(s, pv) / det;
  cross(s, e1, qv);
  const double b2 = dot(dd, qv) / det;
  const double t = dot(e2, qv) / det;
  return {true, t, 1.0 - b1 - b2, b1, b2};
}

// Prints a measured rate in a fixed format and records it as a gtest property.
inline void report_rate(const std::string& what, uint64_t bad, uint64_t total) {
  const double per_million = total ? 1e6 * double(bad) / double(total) : 0.0;
  std::ostringstream line;
  line << what << ": " << bad << " / " << total << " rays = " << std::setprecision(4)
       << per_million << " per million";
  std::cout << "[numerics] " << line.str() << std::endl;
  ::testing::Test::RecordProperty(what, line.str());
}

}  // namespace strata::numerics
