#include "model/stats/stat_contract.h"

#include <stdexcept>

namespace strata::stats {
namespace {

// The sub-group (or instance array, as its merged group) called `name` directly below `g`.
const Group* child_named(const Group& g, const std::string& name) {
  for (const Group::Child& c : g.children()) {
    if (c.group != nullptr && c.group->name() == name) return c.group;
    if (c.instances != nullptr && c.instances->name == name && !c.instances->each.empty())
      return c.instances->each.front();
  }
  return nullptr;
}

}  // namespace

void require_stats(const Group& g, const std::string& owner, const std::vector<Requirement>& contract) {
  for (const Requirement& r : contract) {
    const std::string path = r.path;
    const Group* at = &g;
    size_t begin = 0;
    for (size_t dot; at != nullptr && (dot = path.find('.', begin)) != std::string::npos; begin = dot + 1)
      at = child_named(*at, path.substr(begin, dot - begin));
    const std::string last = path.substr(begin);
    const std::string where = owner + ": its statistics (" + g.name() + ") lack " + path;
    if (at == nullptr) throw std::logic_error(where + ", which the chip reads");
    if (r.group) {
      if (child_named(*at, last) == nullptr) throw std::logic_error(where + " (a group), which the chip reads");
      continue;
    }
    const StatDef* found = nullptr;
    for (const StatDef& s : at->stats())
      if (s.name == last) found = &s;
    if (found == nullptr) throw std::logic_error(where + " [" + unit_name(r.unit) + "], which the chip reads");
    if (found->unit != r.unit)
      throw std::logic_error(owner + ": " + g.name() + "." + path + " is in " + unit_name(found->unit) +
                             ", but the chip reads it in " + unit_name(r.unit));
  }
}

}  // namespace strata::stats
