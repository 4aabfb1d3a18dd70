// A snapshot of the statistics tree: the values of every statistic at one moment, with the
// instance arrays summed, sampled timing's extrapolation applied by each statistic's kind and
// basis, and the ratios and formulas computed on the result. Reports, the summary and the
// statistics reference (docs/statistics.md) are all written from it, so a statistic is
// described in one place and a renamed one is an error, never a silent 0.
#pragma once

#include "model/stats/stat_group.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <set>
#include <string>
#include <vector>

namespace strata::stats {

class Values {
 public:
  struct Stat {
    const StatDef* def = nullptr;  // name, unit, kind, description: the live tree's
    Basis basis = Basis::kExact;   // resolved
    bool integer = true;
    uint64_t u = 0;
    double d = 0.0;
    bool null = false;  // a formula that has no value here (NaN)
    double value() const { return integer ? double(u) : d; }
  };

  // Refreshes the tree (before_snapshot hooks) and reads every source; ratios and formulas
  // are left for derive().
  static Values snapshot(const Group& root);

  // Multiplies every count by its basis's factor (rounded to an integer for integer counts).
  void scale(const Factors& f);
  // Ratios, then formulas, in registration order (a formula may read what precedes it).
  void derive();

  // Sampled timing's intervals (batch_means.h): adds `weight` times `other`'s value of every
  // count whose dotted path `which` accepts, instances included (integer counts rounded). Both
  // trees must come from one statistics tree. A result below zero clamps at zero.
  void combine(const Values& other, double weight,
               const std::function<bool(const std::string&, const Stat&)>& which);
  // Every statistic in tree order with its dotted path (instance arrays: merged values only).
  void visit(const std::function<void(const std::string&, const Stat&)>& f) const;

  // axes: the instance axes to list one by one ("tm", "l2-bank", "channel", ...).
  nlohmann::json to_json(const std::set<std::string>& axes) const;
  // {"dotted.path": "unit"} for every statistic to_json writes without axes.
  nlohmann::json units() const;

  struct Row {
    std::string path, unit, kind, basis, description;
  };
  // One row per statistic, groups first described by a row whose unit is empty.
  std::vector<Row> reference() const;

  // Lookups by dotted path ("memory.l1d.hits"; "memory.dram.channels[2].bytes_read" for one
  // instance of an array); std::out_of_range naming the path when there is none.
  double number(const std::string& path) const;
  uint64_t count(const std::string& path) const;
  bool has(const std::string& path) const;
  const Values& group(const std::string& path) const;
  const Stat& stat(const std::string& path) const;
  // Overwrites one statistic's value (sampled timing's replicates re-estimate the frame time).
  void set(const std::string& path, double value);

  const std::string& name() const { return name_; }
  const std::vector<Stat>& stats() const { return stats_; }
  const std::vector<Values>& children() const { return children_; }
  // Adds a group snapshotted apart (the report's own, e.g. the simulator's speed).
  void append(Values v) { children_.push_back(std::move(v)); }

 private:
  static Values read(const Group& g, Basis inherited);
  static Values merge(const std::vector<Values>& parts);
  void derive_ratios();
  void derive_formulas(const Scope* parent, const Values& root);
  const Values* find_group(const std::string& path) const;
  const Stat* find_stat(const std::string& path) const;
  void collect_units(const std::string& prefix, nlohmann::json& out) const;
  void collect_rows(const std::string& prefix, std::vector<Row>& out) const;
  void combine_at(const std::string& prefix, const Values& other, double weight,
                  const std::function<bool(const std::string&, const Stat&)>& which);
  void visit_at(const std::string& prefix, const std::function<void(const std::string&, const Stat&)>& f) const;

  std::string name_;
  const Group* group_ = nullptr;
  Basis basis_ = Basis::kExact;
  std::vector<Stat> stats_;
  std::vector<Values> children_;
  // Set when this node sums an instance array.
  std::string axis_;
  std::string array_description_;
  bool merged_ = true;
  std::vector<Values> each_;
};

}  // namespace strata::stats
