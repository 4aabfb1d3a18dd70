#include "model/stats/stat_values.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace strata::stats {

const Values& Scope::up(unsigned levels) const {
  const Scope* s = this;
  for (unsigned i = 0; i < levels; ++i) {
    if (s->parent_ == nullptr) throw std::logic_error("formula scope: no ancestor " + std::to_string(levels) + " up");
    s = s->parent_;
  }
  return s->self_;
}

Values Values::snapshot(const Group& root) {
  root.refresh();
  return read(root, Basis::kExact);
}

Values Values::read(const Group& g, Basis inherited) {
  Values v;
  v.name_ = g.name();
  v.group_ = &g;
  v.basis_ = g.basis() == Basis::kInherit ? inherited : g.basis();
  for (const StatDef& d : g.stats()) {
    Stat s;
    s.def = &d;
    s.basis = d.basis == Basis::kInherit ? v.basis_ : d.basis;
    s.integer = d.integer;
    if (d.u64) s.u = *d.u64;
    else if (d.f64) s.d = *d.f64;
    else if (d.u64_probe) s.u = d.u64_probe();
    else if (d.f64_probe) s.d = d.f64_probe();
    v.stats_.push_back(s);
  }
  for (const Group::Child& c : g.children()) {
    if (c.group) {
      v.children_.push_back(read(*c.group, v.basis_));
      continue;
    }
    const Group::Instances& a = *c.instances;
    std::vector<Values> each;
    each.reserve(a.each.size());
    for (const Group* i : a.each) each.push_back(read(*i, v.basis_));
    Values m = merge(each);
    m.name_ = a.name;
    m.axis_ = a.axis;
    m.array_description_ = a.description;
    m.merged_ = a.merged;
    m.each_ = std::move(each);
    v.children_.push_back(std::move(m));
  }
  return v;
}

Values Values::merge(const std::vector<Values>& parts) {
  Values m = parts.front();
  m.each_.clear();
  for (size_t p = 1; p < parts.size(); ++p) {
    const Values& o = parts[p];
    if (o.stats_.size() != m.stats_.size() || o.children_.size() != m.children_.size())
      throw std::logic_error("statistics: instances of '" + m.name_ + "' differ in shape");
    for (size_t i = 0; i < m.stats_.size(); ++i) {
      Stat& s = m.stats_[i];
      if (s.def->kind != Kind::kCount && s.def->kind != Kind::kLevel) continue;  // recomputed
      s.u += o.stats_[i].u;
      s.d += o.stats_[i].d;
    }
  }
  for (size_t c = 0; c < m.children_.size(); ++c) {
    std::vector<Values> column;
    column.reserve(parts.size());
    for (const Values& p : parts) column.push_back(p.children_[c]);
    Values merged = merge(column);
    merged.each_.clear();
    if (!m.children_[c].axis_.empty()) {  // an instance array inside each instance: concatenate
      for (const Values& p : parts)
        for (const Values& e : p.children_[c].each_) merged.each_.push_back(e);
    }
    m.children_[c] = std::move(merged);
  }
  return m;
}

void Values::scale(const Factors& f) {
  for (Stat& s : stats_) {
    if (s.def->kind != Kind::kCount) continue;
    const double k = f[s.basis];
    if (k == 1.0) continue;
    if (s.integer) s.u = static_cast<uint64_t>(std::llround(double(s.u) * k));
    else s.d *= k;
  }
  for (Values& c : children_) c.scale(f);
  for (Values& e : each_) e.scale(f);
}

void Values::combine(const Values& other, double weight,
                     const std::function<bool(const std::string&, const Stat&)>& which) {
  combine_at("", other, weight, which);
}

void Values::combine_at(const std::string& prefix, const Values& o, double weight,
                        const std::function<bool(const std::string&, const Stat&)>& which) {
  if (o.stats_.size() != stats_.size() || o.children_.size() != children_.size() || o.each_.size() != each_.size())
    throw std::logic_error("statistics: snapshots of '" + name_ + "' differ in shape");
  for (size_t i = 0; i < stats_.size(); ++i) {
    Stat& s = stats_[i];
    if (s.def->kind != Kind::kCount || !which(prefix + s.def->name, s)) continue;
    const Stat& t = o.stats_[i];
    if (weight == 1.0) {  // exact in integers: the common case, and what fixed periods need
      s.u += t.u;
    } else if (weight == -1.0) {
      s.u = s.u > t.u ? s.u - t.u : 0;
    } else {
      const double u = double(s.u) + weight * double(t.u);
      s.u = u > 0 ? static_cast<uint64_t>(std::llround(u)) : 0;
    }
    s.d = std::max(0.0, s.d + weight * t.d);
  }
  for (size_t c = 0; c < children_.size(); ++c)
    children_[c].combine_at(prefix + children_[c].name_ + ".", o.children_[c], weight, which);
  for (size_t e = 0; e < each_.size(); ++e) each_[e].combine_at(prefix, o.each_[e], weight, which);
}

void Values::visit(const std::function<void(const std::string&, const Stat&)>& f) const { visit_at("", f); }

void Values::visit_at(const std::string& prefix, const std::function<void(const std::string&, const Stat&)>& f) const {
  for (const Stat& s : stats_) f(prefix + s.def->name, s);
  for (const Values& c : children_) c.visit_at(prefix + c.name_ + ".", f);
}

void Values::set(const std::string& path, double value) {
  Stat& s = const_cast<Stat&>(stat(path));
  if (s.integer) s.u = value > 0 ? static_cast<uint64_t>(std::llround(value)) : 0;
  else s.d = value;
}

void Values::derive() {
  derive_ratios();
  derive_formulas(nullptr, *this);
}

void Values::derive_ratios() {
  for (Stat& s : stats_) {
    if (s.def->kind != Kind::kRatio) continue;
    const double num = stat(s.def->numerator).value();
    double den = 0;
    for (const std::string& d : s.def->denominator) den += stat(d).value();
    s.d = den > 0 ? num / den : 0.0;
  }
  for (Values& c : children_) c.derive_ratios();
  for (Values& e : each_) e.derive_ratios();
}

void Values::derive_formulas(const Scope* parent, const Values& root) {
  const Scope scope(*this, parent, root);
  for (Stat& s : stats_) {
    if (s.def->kind != Kind::kDerived) continue;
    const double v = s.def->formula(scope);
    s.null = std::isnan(v);
    if (s.integer) s.u = s.null ? 0 : static_cast<uint64_t>(std::llround(v));
    else s.d = s.null ? 0.0 : v;
  }
  for (Values& c : children_) c.derive_formulas(&scope, root);
  for (Values& e : each_) e.derive_formulas(&scope, root);
}

namespace {
nlohmann::json stat_json(const Values::Stat& s) {
  if (s.null) return nullptr;
  if (s.integer) return s.u;
  return s.d;
}
}  // namespace

nlohmann::json Values::to_json(const std::set<std::string>& axes) const {
  nlohmann::json j = nlohmann::json::object();
  for (const Stat& s : stats_) j[s.def->name] = stat_json(s);
  for (const Values& c : children_) {
    const bool listed = !c.axis_.empty() && axes.count(c.axis_) > 0;
    if (!c.axis_.empty() && !c.merged_) {
      if (!listed) continue;
      nlohmann::json list = nlohmann::json::array();
      for (const Values& e : c.each_) list.push_back(e.to_json(axes));
      j[c.name_] = std::move(list);
      continue;
    }
    nlohmann::json cj = c.to_json(axes);
    if (listed) {
      nlohmann::json list = nlohmann::json::array();
      for (const Values& e : c.each_) list.push_back(e.to_json(axes));
      cj["per_" + c.axis_] = std::move(list);
    }
    j[c.name_] = std::move(cj);
  }
  return j;
}

void Values::collect_units(const std::string& prefix, nlohmann::json& out) const {
  for (const Stat& s : stats_) out[prefix + s.def->name] = unit_name(s.def->unit);
  for (const Values& c : children_)
    if (c.axis_.empty() || c.merged_) c.collect_units(prefix + c.name_ + ".", out);
}

nlohmann::json Values::units() const {
  nlohmann::json out = nlohmann::json::object();
  collect_units("", out);
  return out;
}

void Values::collect_rows(const std::string& prefix, std::vector<Row>& out) const {
  if (!prefix.empty()) {
    std::string what = group_ ? group_->description() : "";
    if (!axis_.empty()) {
      what += merged_ ? " Summed over every " + array_description_ + "; `--stats-detail " + axis_ +
                            "` lists each under `per_" + axis_ + "`."
                      : " A list with one entry per " + array_description_ + ", written with `--stats-detail " +
                            axis_ + "`.";
    }
    out.push_back(Row{prefix.substr(0, prefix.size() - 1), "", "", basis_name(basis_), what});
  }
  const Values& shape = (!axis_.empty() && !merged_) ? each_.front() : *this;
  const std::string base = (!axis_.empty() && !merged_) ? prefix.substr(0, prefix.size() - 1) + "[]." : prefix;
  for (const Stat& s : shape.stats_) {
    const bool scaled = s.def->kind == Kind::kCount && s.basis != Basis::kExact;
    const bool computed = s.def->kind == Kind::kRatio || s.def->kind == Kind::kDerived;
    out.push_back(Row{base + s.def->name, unit_name(s.def->unit), kind_name(s.def->kind),
                      scaled ? basis_name(s.basis) : computed ? "from its inputs" : "exact", s.def->description});
  }
  for (const Values& c : shape.children_) c.collect_rows(base + c.name_ + ".", out);
}

std::vector<Values::Row> Values::reference() const {
  std::vector<Row> rows;
  collect_rows("", rows);
  return rows;
}

const Values* Values::find_group(const std::string& path) const {
  const Values* g = this;
  size_t start = 0;
  while (start < path.size()) {
    const size_t dot = path.find('.', start);
    std::string part = path.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    // "name[i]": instance i of an instance array.
    size_t index = SIZE_MAX;
    const size_t bracket = part.find('[');
    if (bracket != std::string::npos && part.back() == ']') {
      index = std::stoul(part.substr(bracket + 1, part.size() - bracket - 2));
      part.resize(bracket);
    }
    const Values* next = nullptr;
    for (const Values& c : g->children_)
      if (c.name_ == part) next = &c;
    if (next == nullptr) return nullptr;
    if (index != SIZE_MAX) {
      if (index >= next->each_.size()) return nullptr;
      next = &next->each_[index];
    }
    g = next;
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  return g;
}

const Values::Stat* Values::find_stat(const std::string& path) const {
  const size_t dot = path.rfind('.');
  const Values* g = dot == std::string::npos ? this : find_group(path.substr(0, dot));
  if (g == nullptr) return nullptr;
  const std::string name = dot == std::string::npos ? path : path.substr(dot + 1);
  for (const Stat& s : g->stats_)
    if (s.def->name == name) return &s;
  return nullptr;
}

bool Values::has(const std::string& path) const { return find_stat(path) != nullptr || find_group(path) != nullptr; }

const Values::Stat& Values::stat(const std::string& path) const {
  const Stat* s = find_stat(path);
  if (s == nullptr) throw std::out_of_range("no statistic '" + path + "' in '" + name_ + "'");
  return *s;
}

const Values& Values::group(const std::string& path) const {
  const Values* g = find_group(path);
  if (g == nullptr) throw std::out_of_range("no statistics group '" + path + "' in '" + name_ + "'");
  return *g;
}

double Values::number(const std::string& path) const { return stat(path).value(); }

uint64_t Values::count(const std::string& path) const {
  const Stat& s = stat(path);
  if (!s.integer) throw std::logic_error("statistic '" + path + "' is not an integer");
  return s.u;
}

}  // namespace strata::stats
