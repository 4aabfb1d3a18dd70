#include "model/tm/treelet_sessions.h"

#include <string>

namespace strata::tm {

using stats::Basis;
using stats::Unit;

TreeletSessions::TreeletSessions(uint32_t node_treelets)
    : node_treelets_(node_treelets),
      stats_("sessions",
             "Treelet sessions (streaming designs; 0 on TRaX): a session is the span a TM works on one treelet buffer, "
             "from an assign that returned another treelet than the TM had (or its first) to the next such change; an "
             "assign that found every buffer empty ends none. Its rays are the pops from the TM's buffer meanwhile, "
             "its lines the L1 data lines the TM's loads filled meanwhile (model/tm/treelet_sessions.h). Sampled timing "
             "counts every session of its execution, fast-forward included; in time order (the default) its schedule is "
             "LT's within a few percent.",
             Basis::kExact) {
  register_stats();
}

void TreeletSessions::register_kind(stats::Group& g, const Kind& k) {
  g.count("sessions", &k.sessions, Unit::kCount, "Sessions on treelets of this kind.");
  g.count("rays", &k.rays, Unit::kCount, "Rays traced in them: pops that took a ray from the TM's buffer.");
  g.ratio("rays_per_session", "rays", {"sessions"}, "rays / sessions.");
  g.count("lines_l2_hit", &k.lines.l2_hit, Unit::kCount,
          "L1 data lines filled in them whose line the L2 held (an L2 hit).", Basis::kDataOps);
  g.count("lines_dram", &k.lines.dram, Unit::kCount,
          "L1 data lines filled in them that the L2 missed and read from DRAM.", Basis::kDataOps);
  g.count("lines_l2_merged", &k.lines.l2_merged, Unit::kCount,
          "L1 data lines filled in them that the L2 missed but had on its way from DRAM for an earlier miss (no "
          "second DRAM read).",
          Basis::kDataOps);
  g.count_probe("lines_filled", [&k] { return k.lines.l2_hit + k.lines.dram + k.lines.l2_merged; }, Unit::kCount,
                "L1 data lines filled in them (loads that missed; a miss merged into a fill on its way fills none): "
                "lines_l2_hit + lines_dram + lines_l2_merged.",
                Basis::kDataOps);
  g.ratio("lines_per_session", "lines_filled", {"sessions"}, "lines_filled / sessions.");
  g.ratio("l2_hit_lines_per_session", "lines_l2_hit", {"sessions"}, "lines_l2_hit / sessions.");
  g.ratio("dram_lines_per_session", "lines_dram", {"sessions"}, "lines_dram / sessions.");
}

void TreeletSessions::register_stats() {
  auto sub = [this](const char* name, const char* description, Basis basis = Basis::kInherit) -> stats::Group& {
    groups_.push_back(std::make_unique<stats::Group>(name, description, basis));
    return *groups_.back();
  };
  stats::Group& g = stats_;
  // The open session (each TM's last, at a frame's end) counts with the rays it has so far.
  g.before_snapshot([this] {
    reported_ = closed_;
    if (current_ != transport::kNoTreelet) ++reported_[bucket_of(open_rays_)];
  });
  const Kind& node = kinds_[kNode];
  const Kind& tri = kinds_[kTriangle];
  const auto both = [&node, &tri](uint64_t Kind::*f) { return [&node, &tri, f] { return node.*f + tri.*f; }; };
  const auto both_lines = [&node, &tri](uint64_t Lines::*f) {
    return [&node, &tri, f] { return node.lines.*f + tri.lines.*f; };
  };
  g.count_probe("sessions", both(&Kind::sessions), Unit::kCount,
                "Sessions: treelet buffers the TM took (node + triangle).");
  g.count_probe("rays", both(&Kind::rays), Unit::kCount,
                "Rays traced in sessions: pops that took a ray from the TM's buffer (node + triangle).");
  g.count("rays_popped", &rays_popped_, Unit::kCount,
          "Pops by the TM's TPs that took a ray, counted apart: equals rays (every ray is popped in a session).");
  g.ratio("rays_per_session", "rays", {"sessions"}, "rays / sessions.");
  g.count_probe("lines_l2_hit", both_lines(&Lines::l2_hit), Unit::kCount,
                "L1 data lines filled in sessions whose line the L2 held (an L2 hit).", Basis::kDataOps);
  g.count_probe("lines_dram", both_lines(&Lines::dram), Unit::kCount,
                "L1 data lines filled in sessions that the L2 missed and read from DRAM.", Basis::kDataOps);
  g.count_probe("lines_l2_merged", both_lines(&Lines::l2_merged), Unit::kCount,
                "L1 data lines filled in sessions that the L2 missed but had on its way from DRAM for an earlier "
                "miss (no second DRAM read).",
                Basis::kDataOps);
  g.count_probe("lines_filled",
                [&node, &tri] {
                  return node.lines.l2_hit + node.lines.dram + node.lines.l2_merged + tri.lines.l2_hit +
                         tri.lines.dram + tri.lines.l2_merged;
                },
                Unit::kCount,
                "L1 data lines filled in sessions (loads that missed; a miss merged into a fill on its way fills "
                "none): lines_l2_hit + lines_dram + lines_l2_merged. With lines_outside_sessions, the L1's fills.",
                Basis::kDataOps);
  g.count_probe("lines_outside_sessions", [this] { return outside_.l2_hit + outside_.dram + outside_.l2_merged; },
                Unit::kCount, "L1 data lines filled before the TM took its first treelet buffer (streaming designs only: 0 on TRaX).",
                Basis::kDataOps);
  g.ratio("lines_per_session", "lines_filled", {"sessions"}, "lines_filled / sessions.");
  g.ratio("l2_hit_lines_per_session", "lines_l2_hit", {"sessions"}, "lines_l2_hit / sessions.");
  g.ratio("dram_lines_per_session", "lines_dram", {"sessions"}, "lines_dram / sessions.");

  stats::Group& nodes = sub("node", "Sessions on node treelets (box tests only).");
  register_kind(nodes, node);
  g.child(&nodes);
  stats::Group& triangles = sub("triangle", "Sessions on triangle treelets (triangle tests only).");
  register_kind(triangles, tri);
  g.child(&triangles);

  stats::Group& h = sub("rays_histogram",
                        "Sessions by the rays they traced: zero, then from_N holds sessions of N to 2N - 1 rays (N a "
                        "power of two); the last bucket has no upper end. The buckets sum to sessions.");
  h.count("zero", &reported_[0], Unit::kCount, "Sessions that traced no ray (other TMs emptied the buffer first).");
  for (unsigned b = 1; b < kBuckets; ++b) {
    const uint64_t from = uint64_t{1} << (b - 1);
    const std::string name = "from_" + std::to_string(from);
    const std::string what = b + 1 < kBuckets ? "Sessions of " + std::to_string(from) + " to " +
                                                    std::to_string(2 * from - 1) + " rays."
                                              : "Sessions of " + std::to_string(from) + " rays or more.";
    h.count(name.c_str(), &reported_[b], Unit::kCount, what.c_str());
  }
  g.child(&h);
}

}  // namespace strata::tm
