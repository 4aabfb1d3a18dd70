// docs/config-ranges.md against the code: the table lists every bound config field once, with
// the built-in default, and its accepted range is what load_chip_config accepts. Each range is
// probed at its ends (accepted) and just outside them (refused, with an error naming the field
// or a field its notes name), in the row's "checked with" context.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "model/chip/chip_config.h"

namespace strata::chip {
namespace {

struct Row {
  int line = 0;
  std::string field, unit, default_value, accepted;
  std::vector<std::string> context;  // --set overrides the range is checked with
  std::vector<std::string> named;    // fields an error for this row may name instead
};

std::string trim(const std::string& s) {
  const size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

std::vector<std::string> backticked(const std::string& s) {
  std::vector<std::string> out;
  const std::regex re("`([^`]*)`");
  for (auto it = std::sregex_iterator(s.begin(), s.end(), re); it != std::sregex_iterator(); ++it)
    out.push_back((*it)[1]);
  return out;
}

std::vector<Row> read_table() {
  std::ifstream in(std::string(STRATA_SOURCE_DIR) + "/docs/config-ranges.md");
  EXPECT_TRUE(in) << "docs/config-ranges.md not found";
  std::vector<Row> rows;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    if (text.rfind("| `", 0) != 0) continue;  // table rows start with a field name
    std::vector<std::string> cells;
    std::stringstream ss(text.substr(1));
    std::string cell;
    while (std::getline(ss, cell, '|')) cells.push_back(trim(cell));
    EXPECT_EQ(cells.size(), 6u) << "docs/config-ranges.md:" << line << ": expected 6 cells";
    if (cells.size() != 6) continue;
    Row r;
    r.line = line;
    r.field = backticked(cells[0]).at(0);
    r.unit = cells[1];
    const auto d = backticked(cells[2]);
    r.default_value = d.empty() ? "" : d[0];
    r.accepted = cells[3];
    for (const std::string& c : backticked(cells[4])) {
      std::stringstream cs(c);
      std::string o;
      while (cs >> o) r.context.push_back(o);
    }
    for (const std::string& n : backticked(cells[5]))
      if (n.find('.') != std::string::npos || n.find('_') != std::string::npos) r.named.push_back(n);
    rows.push_back(r);
  }
  return rows;
}

// The built-in defaults with path state in DRAM: 52 bytes of stream memory per ray, the fewest
// of the three placements (on chip, the path records would leave 512 KiB of stream memory 3483
// rays for 4096 TPs), and each design file sets its own sizes.
const char* const kBase = "design.path_state=dram";

// "" when accepted, else the error.
std::string load(const Row& r, const std::string& value) {
  std::vector<std::string> overrides = {kBase};
  overrides.insert(overrides.end(), r.context.begin(), r.context.end());
  overrides.push_back(r.field + "=" + value);
  try {
    load_chip_config("", overrides);
  } catch (const ConfigError& e) {
    return std::string("refused: ") + e.what();
  }
  return "";
}

// An error names a field when it holds its dotted path, or that path without the section
// (the memory, tm and energy sections prefix their messages with their own name).
bool names(const std::string& error, const std::string& field) {
  if (error.find(field) != std::string::npos) return true;
  const size_t dot = field.find('.');
  return dot != std::string::npos && error.find(field.substr(dot + 1)) != std::string::npos;
}

void expect_refused(const Row& r, const std::string& value) {
  const std::string e = load(r, value);
  if (e.empty()) {
    ADD_FAILURE() << "docs/config-ranges.md:" << r.line << ": " << r.field << "=" << value
                  << " is accepted, outside '" << r.accepted << "'";
    return;
  }
  bool named = names(e, r.field);
  for (const std::string& n : r.named) named = named || names(e, n);
  EXPECT_TRUE(named) << "docs/config-ranges.md:" << r.line << ": " << r.field << "=" << value
                     << ": the error names neither the field nor one its notes name: " << e;
}

void expect_accepted(const Row& r, const std::string& value) {
  EXPECT_EQ(load(r, value), "") << "docs/config-ranges.md:" << r.line << ": " << r.field << "=" << value
                                << " is inside '" << r.accepted << "'";
}

std::string number(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

// Integers: "A..B", optionally ", power of two" or ", multiple of N".
bool check_integer_range(const Row& r) {
  static const std::regex re(R"(^(\d+)\.\.(\d+)(, power of two|, multiple of (\d+))?$)");
  std::smatch m;
  if (!std::regex_match(r.accepted, m, re)) return false;
  const uint64_t lo = std::stoull(m[1]), hi = std::stoull(m[2]);
  const bool pow2 = m[3] == ", power of two";
  const uint64_t multiple = m[4].matched ? std::stoull(m[4]) : 1;
  EXPECT_LE(lo, hi) << r.field;
  expect_accepted(r, std::to_string(lo));
  expect_accepted(r, std::to_string(hi));
  if (lo > 0) expect_refused(r, std::to_string(pow2 ? lo / 2 : lo - 1));
  if (hi < std::numeric_limits<uint32_t>::max()) expect_refused(r, std::to_string(pow2 ? hi * 2 : hi + 1));
  if (pow2 && lo >= 2 && lo * 3 / 2 < hi) expect_refused(r, std::to_string(lo * 3 / 2));
  if (pow2 && lo == 1 && hi >= 4) expect_refused(r, "3");
  if (multiple > 1 && lo + 1 < hi) expect_refused(r, std::to_string(lo + 1));
  return true;
}

// Reals: intervals "[a, b]", "(a, b]", "[a, b)", "(a, b)" or single values, joined by " or ";
// "null" for an optional value. Each end is probed, and a point just beyond it on both sides.
bool check_real_range(const Row& r) {
  struct Interval {
    double lo, hi;
    bool lo_open, hi_open;
  };
  std::vector<Interval> parts;
  bool null_ok = false;
  static const std::regex interval(R"(^([\[(])([-0-9.e+]+), ([-0-9.e+]+)([\])])$)");
  static const std::regex point(R"(^[-0-9.e+]+$)");
  std::string rest = r.accepted;
  while (!rest.empty()) {
    const size_t sep = rest.find(" or ");
    const std::string part = rest.substr(0, sep);
    rest = sep == std::string::npos ? "" : rest.substr(sep + 4);
    std::smatch m;
    if (part == "null") {
      null_ok = true;
    } else if (std::regex_match(part, m, interval)) {
      parts.push_back({std::stod(m[2]), std::stod(m[3]), m[1] == "(", m[4] == ")"});
    } else if (std::regex_match(part, point)) {
      const double v = std::stod(part);
      parts.push_back({v, v, false, false});
    } else {
      return false;
    }
  }
  if (parts.empty()) return false;
  const auto inside = [&](double v) {
    for (const Interval& p : parts)
      if ((p.lo_open ? v > p.lo : v >= p.lo) && (p.hi_open ? v < p.hi : v <= p.hi)) return true;
    return false;
  };
  for (const Interval& p : parts)
    for (double end : {p.lo, p.hi}) {
      const double step = end == 0 ? 1e-9 : std::fabs(end) * 1e-6;
      for (double v : {end - step, end, end + step}) {
        if (inside(v)) expect_accepted(r, number(v));
        else expect_refused(r, number(v));
      }
    }
  if (null_ok) expect_accepted(r, "null");
  else expect_refused(r, "null");
  return true;
}

TEST(ConfigRanges, TheTableListsEveryFieldOnce) {
  ConfigBinder binder;
  ChipConfig config;
  config.bind(binder);
  const auto paths = binder.paths();
  const std::set<std::string> bound(paths.begin(), paths.end());
  std::map<std::string, int> listed;
  for (const Row& r : read_table()) {
    EXPECT_EQ(listed[r.field]++, 0) << "docs/config-ranges.md:" << r.line << ": " << r.field << " listed twice";
    EXPECT_EQ(bound.count(r.field), 1u) << "docs/config-ranges.md:" << r.line << ": " << r.field
                                        << " is not a config field";
  }
  for (const std::string& p : bound) EXPECT_EQ(listed.count(p), 1u) << p << " is missing from docs/config-ranges.md";
}

TEST(ConfigRanges, DefaultsAreTheBuiltInOnes) {
  const ChipConfig built_in;  // a named object: GCC 12 warns (falsely) about a temporary's strings
  const nlohmann::json defaults = to_json(built_in);
  for (const Row& r : read_table()) {
    std::string pointer = "/" + r.field;
    for (char& c : pointer)
      if (c == '.') c = '/';
    const nlohmann::json::json_pointer at(pointer);
    ASSERT_TRUE(defaults.contains(at)) << r.field;
    EXPECT_EQ(nlohmann::json::parse(r.default_value, nullptr, false), defaults[at])
        << "docs/config-ranges.md:" << r.line << ": " << r.field << " defaults to " << defaults[at].dump();
  }
}

TEST(ConfigRanges, EachRangeIsWhatTheConfigAccepts) {
  const ChipConfig built_in;  // a named object: GCC 12 warns (falsely) about a temporary's strings
  const nlohmann::json defaults = to_json(built_in);
  const std::vector<Row> rows = read_table();
  ASSERT_GT(rows.size(), 90u);
  for (const Row& r : rows) {
    SCOPED_TRACE(r.field);
    // The context alone must load, or a refusal would say nothing about the field.
    Row base = r;
    EXPECT_EQ(load(base, r.default_value), "") << "docs/config-ranges.md:" << r.line << ": context "
                                              << ::testing::PrintToString(r.context);
    if (r.accepted == "true, false") {
      expect_accepted(r, "true");
      expect_accepted(r, "false");
      expect_refused(r, "1");
    } else if (r.accepted == "the design's") {  // design.streams, design.pipelines: design.name decides
      expect_accepted(r, r.default_value);
      expect_refused(r, r.default_value == "true" ? "false" : "true");
      expect_refused(r, "1");
    } else if (r.accepted == "any string") {
      expect_accepted(r, "\"x\"");
      expect_refused(r, "1");
    } else if (r.accepted == "`all` or TM indices below `tms`") {  // tm.pipeline_impl_tms (tms: 128)
      for (const char* v : {"\"all\"", "\"0\"", "\"0,127\"", "127"}) expect_accepted(r, v);
      for (const char* v : {"\"0,128\"", "128", "\"\"", "\"0,\"", "\"x\"", "-1", "true"}) expect_refused(r, v);
    } else if (r.accepted == "comma-separated statistics") {  // timing.sample_target_stats
      for (const char* v : {"\"frame.cycles\"", "\"memory.dram.bytes, frame.cycles\""}) expect_accepted(r, v);
      for (const char* v : {"\"\"", "\"frame.cycles,\"", "\"a,,b\"", "\"a,a\"", "1"}) expect_refused(r, v);
    } else if (r.accepted.rfind("one of ", 0) == 0) {
      for (const std::string& name : backticked(r.accepted)) expect_accepted(r, "\"" + name + "\"");
      expect_refused(r, "\"none-of-these\"");
    } else {
      const bool ok = check_integer_range(r) || check_real_range(r);
      EXPECT_TRUE(ok) << "docs/config-ranges.md:" << r.line << ": cannot read the range '" << r.accepted << "'";
    }
  }
}

}  // namespace
}  // namespace strata::chip
