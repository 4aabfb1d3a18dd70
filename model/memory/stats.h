// A statistics tree. Each module keeps its counters as plain members (incrementing one on
// the hot path is an add, never a lookup or a virtual call) and registers their addresses
// here once, by name. A parent adds its children's groups and writes the tree as JSON.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace strata::memory {

class StatGroup {
 public:
  explicit StatGroup(std::string name) : name_(std::move(name)) {}

  void add(std::string name, const uint64_t* counter) { counters_.emplace_back(std::move(name), counter); }
  void add(std::string name, const double* value) { values_.emplace_back(std::move(name), value); }
  void add(std::initializer_list<std::pair<const char*, const uint64_t*>> counters) {
    for (const auto& [name, p] : counters) add(name, p);
  }
  void add_child(const StatGroup* child) { children_.push_back(child); }

  const std::string& name() const { return name_; }
  const std::vector<const StatGroup*>& children() const { return children_; }
  // {"counter": n, ..., "child": {...}}
  nlohmann::json to_json() const;
  // Value of a counter or value by dotted path below this group ("channel0.bytes_read");
  // throws std::out_of_range if there is none.
  double get(const std::string& path) const;

 private:
  std::string name_;
  std::vector<std::pair<std::string, const uint64_t*>> counters_;
  std::vector<std::pair<std::string, const double*>> values_;
  std::vector<const StatGroup*> children_;
};

}  // namespace strata::memory
