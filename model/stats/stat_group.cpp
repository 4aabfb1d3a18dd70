#include "model/stats/stat_group.h"

#include <stdexcept>

namespace strata::stats {

const char* unit_name(Unit u) {
  switch (u) {
    case Unit::kCount: return "count";
    case Unit::kBytes: return "bytes";
    case Unit::kCycles: return "cycles";
    case Unit::kNanojoules: return "nJ";
    case Unit::kSeconds: return "s";
    case Unit::kRatio: return "ratio";
    case Unit::kGigabytesPerSecond: return "GB/s";
    case Unit::kPerSecond: return "1/s";
    case Unit::kGigahertz: return "GHz";
  }
  return "?";
}

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::kCount: return "count";
    case Kind::kLevel: return "level";
    case Kind::kRatio: return "ratio";
    case Kind::kDerived: return "derived";
  }
  return "?";
}

const char* basis_name(Basis b) {
  switch (b) {
    case Basis::kInherit: return "inherit";
    case Basis::kExact: return "exact";
    case Basis::kTimedInstructions: return "timed instructions";
    case Basis::kMeasuredInstructions: return "measured instructions";
    case Basis::kDataOps: return "data operations";
    case Basis::kStreamOps: return "stream operations";
    case Basis::kStreamMoves: return "ray pushes and pops";
    case Basis::kCount: break;
  }
  return "?";
}

StatDef& Group::add(const char* name, Unit u, Kind k, const char* description, Basis basis) {
  for (const StatDef& s : stats_)
    if (s.name == name) throw std::logic_error("statistic '" + s.name + "' registered twice in '" + name_ + "'");
  StatDef& s = stats_.emplace_back();
  s.name = name;
  s.description = description;
  s.unit = u;
  s.kind = k;
  s.basis = basis;
  return s;
}

Group& Group::count(const char* name, const uint64_t* v, Unit u, const char* description, Basis basis) {
  add(name, u, Kind::kCount, description, basis).u64 = v;
  return *this;
}

Group& Group::count(const char* name, const double* v, Unit u, const char* description, Basis basis) {
  StatDef& s = add(name, u, Kind::kCount, description, basis);
  s.f64 = v;
  s.integer = false;
  return *this;
}

Group& Group::count_probe(const char* name, std::function<uint64_t()> probe, Unit u, const char* description,
                          Basis basis) {
  add(name, u, Kind::kCount, description, basis).u64_probe = std::move(probe);
  return *this;
}

Group& Group::level(const char* name, const uint64_t* v, Unit u, const char* description) {
  add(name, u, Kind::kLevel, description, Basis::kExact).u64 = v;
  return *this;
}

Group& Group::level_integer(const char* name, std::function<uint64_t()> probe, Unit u, const char* description) {
  add(name, u, Kind::kLevel, description, Basis::kExact).u64_probe = std::move(probe);
  return *this;
}

Group& Group::level_real(const char* name, std::function<double()> probe, Unit u, const char* description) {
  StatDef& s = add(name, u, Kind::kLevel, description, Basis::kExact);
  s.f64_probe = std::move(probe);
  s.integer = false;
  return *this;
}

Group& Group::ratio(const char* name, const char* numerator, std::vector<std::string> denominator,
                    const char* description) {
  StatDef& s = add(name, Unit::kRatio, Kind::kRatio, description, Basis::kExact);
  s.integer = false;
  s.numerator = numerator;
  s.denominator = std::move(denominator);
  return *this;
}

Group& Group::derived(const char* name, Unit u, const char* description, Formula f, bool integer) {
  StatDef& s = add(name, u, Kind::kDerived, description, Basis::kExact);
  s.integer = integer;
  s.formula = std::move(f);
  return *this;
}

Group& Group::child(const Group* g) {
  order_.push_back(Child{g, nullptr});
  return *this;
}

Group& Group::instances(const char* name, std::vector<const Group*> each, const char* axis,
                        const char* description, bool merged) {
  if (each.empty()) throw std::logic_error(std::string("instance array '") + name + "' has no instances");
  instance_arrays_.push_back(std::make_unique<Instances>(Instances{name, axis, description, std::move(each), merged}));
  order_.push_back(Child{nullptr, instance_arrays_.back().get()});
  return *this;
}

Group& Group::before_snapshot(std::function<void()> refresh) {
  refresh_.push_back(std::move(refresh));
  return *this;
}

void Group::refresh() const {
  for (const auto& r : refresh_) r();
  for (const Child& c : order_) {
    if (c.group) c.group->refresh();
    if (c.instances)
      for (const Group* g : c.instances->each) g->refresh();
  }
}

}  // namespace strata::stats
