// The live statistics tree. Each module keeps its counters as plain members, so counting on
// the hot path is an add, never a lookup or a virtual call, and registers them here once, at
// construction, with a name, a unit, a kind and a one-line description. A parent adds its
// children's groups; instance arrays (the TMs' L1s, the DRAM channels) are registered as
// one node that a report sums, and lists one by one on request.
//
// Nothing here is read until a report takes a snapshot (stat_values.h).
#pragma once

#include "model/stats/statistic.h"

#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace strata::stats {

class Values;

// Where a formula (Kind::kDerived) reads: its own group's snapshot, its ancestors' and the
// root's. Paths are dotted ("memory.l1d.hits").
class Scope {
 public:
  Scope(const Values& self, const Scope* parent, const Values& root) : self_(self), parent_(parent), root_(root) {}
  const Values& self() const { return self_; }
  const Values& up(unsigned levels) const;  // up(0) == self()
  const Values& root() const { return root_; }

 private:
  const Values& self_;
  const Scope* parent_;
  const Values& root_;
};
// Returns the value; a NaN is written as null (e.g. a frame rate of a frame that did not finish).
using Formula = std::function<double(const Scope&)>;

struct StatDef {
  std::string name;
  std::string description;
  Unit unit = Unit::kCount;
  Kind kind = Kind::kCount;
  Basis basis = Basis::kInherit;
  bool integer = true;                  // written as an integer
  const uint64_t* u64 = nullptr;        // one of these four is the source of a count or level
  const double* f64 = nullptr;
  std::function<uint64_t()> u64_probe;
  std::function<double()> f64_probe;
  std::string numerator;                // kRatio: names in the same group
  std::vector<std::string> denominator; // summed
  Formula formula;                      // kDerived
};

class Group {
 public:
  Group(std::string name, std::string description, Basis basis = Basis::kInherit)
      : name_(std::move(name)), description_(std::move(description)), basis_(basis) {}
  Group(const Group&) = delete;  // the tree and the probes point at it
  Group& operator=(const Group&) = delete;

  // Events (Kind::kCount). `basis` overrides the group's for this statistic.
  Group& count(const char* name, const uint64_t* v, Unit u, const char* description, Basis basis = Basis::kInherit);
  Group& count(const char* name, const double* v, Unit u, const char* description, Basis basis = Basis::kInherit);
  // Read through a function at snapshot time (e.g. a sum the module keeps elsewhere).
  Group& count_probe(const char* name, std::function<uint64_t()> probe, Unit u, const char* description,
                     Basis basis = Basis::kInherit);
  // Sizes and states (Kind::kLevel); a probe returning an integer is written as one.
  Group& level(const char* name, const uint64_t* v, Unit u, const char* description);
  template <class F, class = std::enable_if_t<std::is_invocable_v<F>>>
  Group& level(const char* name, F probe, Unit u, const char* description) {
    if constexpr (std::is_floating_point_v<std::invoke_result_t<F>>)
      return level_real(name, std::function<double()>(std::move(probe)), u, description);
    else
      return level_integer(name, std::function<uint64_t()>([p = std::move(probe)] { return uint64_t(p()); }), u,
                           description);
  }
  Group& level_integer(const char* name, std::function<uint64_t()> probe, Unit u, const char* description);
  Group& level_real(const char* name, std::function<double()> probe, Unit u, const char* description);
  // numerator / (sum of denominator), statistics of this group (Kind::kRatio; 0 if the sum is 0).
  Group& ratio(const char* name, const char* numerator, std::vector<std::string> denominator,
               const char* description);
  // Computed after everything else is merged and scaled (Kind::kDerived).
  Group& derived(const char* name, Unit u, const char* description, Formula f, bool integer = false);

  // A sub-group, owned by its module; it must outlive this group.
  Group& child(const Group* g);
  // One node for N groups of the same shape (one per TM, per bank, per channel). Reports sum
  // it as one group named `name`, and list each instance under "per_<axis>" when the axis is
  // asked for. `merged` false: no sum, the list alone, under `name`, when the axis is shown.
  Group& instances(const char* name, std::vector<const Group*> each, const char* axis, const char* description,
                   bool merged = true);
  // Runs before every snapshot: a module refreshes statistics it keeps elsewhere (sums
  // over its TPs, a crossbar's state up to now).
  Group& before_snapshot(std::function<void()> refresh);

  struct Instances {
    std::string name, axis, description;
    std::vector<const Group*> each;
    bool merged;
  };
  struct Child {  // a sub-group or an instance array, in registration order
    const Group* group = nullptr;
    const Instances* instances = nullptr;
  };

  const std::string& name() const { return name_; }
  const std::string& description() const { return description_; }
  Basis basis() const { return basis_; }
  const std::vector<StatDef>& stats() const { return stats_; }
  const std::vector<Child>& children() const { return order_; }
  void refresh() const;  // the before_snapshot hooks of this group and everything below

 private:
  StatDef& add(const char* name, Unit u, Kind k, const char* description, Basis basis);

  std::string name_;
  std::string description_;
  Basis basis_;
  std::vector<StatDef> stats_;
  std::vector<std::unique_ptr<Instances>> instance_arrays_;
  std::vector<Child> order_;
  std::vector<std::function<void()>> refresh_;
};

}  // namespace strata::stats
