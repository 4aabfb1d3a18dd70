#include "model/memory/stats.h"

#include <stdexcept>

namespace strata::memory {

nlohmann::json StatGroup::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, p] : counters_) j[name] = *p;
  for (const auto& [name, p] : values_) j[name] = *p;
  for (const StatGroup* c : children_) j[c->name()] = c->to_json();
  return j;
}

double StatGroup::get(const std::string& path) const {
  const auto dot = path.find('.');
  if (dot != std::string::npos) {
    const std::string head = path.substr(0, dot);
    for (const StatGroup* c : children_)
      if (c->name() == head) return c->get(path.substr(dot + 1));
  } else {
    for (const auto& [name, p] : counters_)
      if (name == path) return static_cast<double>(*p);
    for (const auto& [name, p] : values_)
      if (name == path) return *p;
  }
  throw std::out_of_range("no statistic '" + path + "' in group '" + name_ + "'");
}

}  // namespace strata::memory
