// `--vcd`: the chip registers its traces before the simulation starts, and the file holds the
// expected signals with real value changes.
#include <fstream>
#include <map>
#include <sstream>

#include "chip_support.h"

namespace strata::chip::test {
namespace {

// Signal names by VCD identifier code, and how many value changes each one had.
struct Vcd {
  std::map<std::string, std::string> name_of;
  std::map<std::string, int> changes;
  std::map<std::string, uint64_t> first_change, last_change;  // timestamps after time 0
};

Vcd parse_vcd(const std::string& path) {
  Vcd v;
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> scope;
  bool in_dump = false;
  uint64_t now = 0;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string tok;
    s >> tok;
    if (tok == "$scope") {
      std::string kind, name;
      s >> kind >> name;
      scope.push_back(name);
    } else if (tok == "$upscope") {
      scope.pop_back();
    } else if (tok == "$var") {
      std::string type, width, code, name;
      s >> type >> width >> code >> name;
      std::string full;
      for (const auto& part : scope) full += part + ".";
      v.name_of[code] = full + name;
    } else if (tok == "$enddefinitions") {
      in_dump = true;
    } else if (in_dump && !tok.empty() && tok[0] == '#') {
      now = std::stoull(tok.substr(1));
    } else if (in_dump && !tok.empty() && tok[0] != '$') {
      std::string code;
      if (tok[0] == 'r' || tok[0] == 'b') s >> code; else code = tok.substr(1);
      ++v.changes[code];
      if (now > 0) {
        if (!v.first_change.count(code)) v.first_change[code] = now;
        v.last_change[code] = now;
      }
    }
  }
  return v;
}

TEST(ChipVcd, TraceHoldsTheTmCacheAndDramSignalsWithValueChanges) {
  REQUIRE_KERNEL("baseline");
  const SmallFrame frame(scenes::make_cornell({0.2, 1}), 8);
  const sim::PreparedFrame f = frame.on(small_chip(transport::TimingMode::kLooselyTimed));
  Chip chip("chip", f.config, f.inputs);
  const std::string base = (std::filesystem::temp_directory_path() / ("strata-vcd-" + std::to_string(::getpid()))).string();
  sc_core::sc_trace_file* file = sc_core::sc_create_vcd_trace_file(base.c_str());
  chip.trace(file, memory::TraceWindow(500));
  sc_core::sc_start();
  sc_core::sc_close_vcd_trace_file(file);
  ASSERT_TRUE(chip.finished()) << chip.error();

  const Vcd v = parse_vcd(base + ".vcd");
  std::filesystem::remove(base + ".vcd");
  auto find = [&](const std::string& needle) {
    for (const auto& [code, name] : v.name_of)
      if (name.find(needle) != std::string::npos) return code;
    return std::string();
  };
  for (const char* signal : {"tm_0.instructions", "tm_1.pipeline_mode", "tm_0.treelet", "l1d_0", "dram"})
    EXPECT_FALSE(find(signal).empty()) << "no VCD signal containing " << signal;
  const std::string instructions = find("tm_0.instructions");
  ASSERT_FALSE(instructions.empty());
  // Thousands of cycles in windows of 500: the instruction rate changes many times.
  EXPECT_GT(v.changes.count(instructions) ? v.changes.at(instructions) : 0, 3);
}

// --vcd-start/--vcd-end: only windows starting inside [start, end) change the trace.
TEST(ChipVcd, TimeWindowKeepsTheTraceToTheRequestedCycles) {
  REQUIRE_KERNEL("baseline");
  const SmallFrame frame(scenes::make_cornell({0.2, 1}), 8);
  const sim::PreparedFrame f = frame.on(small_chip(transport::TimingMode::kLooselyTimed));
  Chip chip("chip", f.config, f.inputs);
  const std::string base = (std::filesystem::temp_directory_path() / ("strata-vcdw-" + std::to_string(::getpid()))).string();
  sc_core::sc_trace_file* file = sc_core::sc_create_vcd_trace_file(base.c_str());
  file->set_time_unit(1, sc_core::SC_NS);
  chip.trace(file, memory::TraceWindow(500, 20000, 30000));
  sc_core::sc_start();
  sc_core::sc_close_vcd_trace_file(file);
  ASSERT_TRUE(chip.finished()) << chip.error();
  ASSERT_GT(chip.cycles(), 40000u);  // the run is longer than the window
  const Vcd v = parse_vcd(base + ".vcd");
  std::filesystem::remove(base + ".vcd");
  int traced = 0;
  for (const auto& [code, name] : v.name_of) {
    if (name.find("tm_0.instructions") == std::string::npos) continue;
    ++traced;
    ASSERT_TRUE(v.first_change.count(code)) << "no change inside the window";
    // A window is published when the first access after it arrives: within a window or two.
    EXPECT_GE(v.first_change.at(code), 20000u);
    EXPECT_LE(v.last_change.at(code), 32000u);
  }
  EXPECT_EQ(traced, 1);
}

}  // namespace
}  // namespace strata::chip::test
