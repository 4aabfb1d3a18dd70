// strata-embree-trace: traces a ray file with Embree 3 (robust mode, one thread) and writes
// a hit file in strata-sim's format, so `strata-sim trace` can be compared with an
// independent tracer on the same rays, for agreement and for speed.
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>

#include "sim/ray_file.h"
#include "scenes/scene_spec.h"
#include "tools/oracle/embree_oracle.h"

int main(int argc, char** argv) {
  CLI::App app{"Trace a strata ray file with Embree 3 (the independent oracle)"};
  std::string scene_spec, rays_in, out;
  app.add_option("--scene", scene_spec, "scene spec, as for strata-sim")->required();
  app.add_option("--rays", rays_in, "ray file (STRAYS01)")->required();
  app.add_option("--out", out, "hit file to write (STRHITS1)")->required();
  CLI11_PARSE(app, argc, argv);
  try {
    using namespace strata;
    const std::vector<sim::RayRecord> rays = sim::read_ray_file(rays_in);
    const scenes::Scene scene = scenes::load_scene(scene_spec, STRATA_SOURCE_DIR);
    const oracle::EmbreeScene embree(scene.triangles);
    std::vector<sim::HitRecord> hits(rays.size());
    uint64_t hit_count = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (size_t i = 0; i < rays.size(); ++i) {
      const sim::RayRecord& r = rays[i];
      const oracle::OracleHit h = embree.intersect(r.origin, r.dir, r.tmin, r.tmax);
      hits[i] = h.hit ? sim::HitRecord{h.t, h.primitive, h.u, h.v}
                      : sim::HitRecord{INFINITY, sim::kMissPrimitive, 0.0f, 0.0f};
      hit_count += h.hit ? 1 : 0;
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    sim::write_hit_file(out, hits);
    std::printf("embree           %s, robust scene, 1 thread, rtcIntersect1\n", oracle::EmbreeScene::version().c_str());
    std::printf("rays             %zu, %llu hits\n", rays.size(), static_cast<unsigned long long>(hit_count));
    std::printf("speed            %.2f MRays/s (%.3f s wall clock for tracing)\n",
                s > 0 ? double(rays.size()) / s * 1e-6 : 0.0, s);
  } catch (const std::exception& e) {
    std::cerr << "strata-embree-trace: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
