// Design configs: the three shipped files load; every field can be overridden; bad files,
// unknown keys, wrong types and impossible values are errors that name the field.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "config_support.h"
#include "model/chip/chip_config.h"

namespace strata::chip {
namespace {

using test::config_dir;
using test::error_of;

TEST(ChipConfig, TheThreeDesignsLoad) {
  const ChipConfig trax = load_chip_config(config_dir() + "trax.json", {});
  const ChipConfig streams = load_chip_config(config_dir() + "strata-streams.json", {});
  const ChipConfig pipes = load_chip_config(config_dir() + "strata-pipelines.json", {});
  EXPECT_FALSE(trax.design.streams);
  EXPECT_FALSE(trax.design.pipelines);
  EXPECT_EQ(trax.l2.size_bytes, 4u << 20);
  EXPECT_TRUE(streams.design.streams);
  EXPECT_FALSE(streams.design.pipelines);
  EXPECT_TRUE(pipes.design.pipelines);
  EXPECT_EQ(pipes.l2.size_bytes, 512u << 10);
  EXPECT_EQ(pipes.tms, 128u);
  EXPECT_EQ(pipes.stream.threads, 128u * 32u);  // derived
}

// The STRaTA designs ship with the compact path state (64-byte rays, 68 B of SRAM each with the
// link), so a 512 KB stream memory holds a ray per TP of 128 TMs; 148 B with a path record on
// chip does not, and the error says how many rays it holds.
TEST(ChipConfig, HalfAMegabyteOfStreamMemoryRunsWithTheCompactPathState) {
  const std::string streams = config_dir() + "strata-streams.json";
  const ChipConfig c = load_chip_config(streams, {"memory.stream.size_bytes=524288"});
  EXPECT_EQ(c.design.path_state, PathStatePlacement::kCompact);
  EXPECT_EQ(c.stream.ray_bytes, 64u);
  EXPECT_EQ(c.stream.path_record_bytes, 0u);
  EXPECT_EQ(c.tms * c.tps_per_tm, 4096u);
  const std::string refused = error_of(streams, {"memory.stream.size_bytes=524288", "design.path_state=on-chip"});
  EXPECT_NE(refused.find("memory.stream.size_bytes"), std::string::npos) << refused;
  EXPECT_NE(refused.find("fewer than one per TP"), std::string::npos) << refused;
  EXPECT_NE(error_of(streams, {"design.path_state=compressed"}).find("design.path_state"), std::string::npos);
}

TEST(ChipConfig, OverridesReachNestedFieldsAndRoundTripThroughJson) {
  const ChipConfig c = load_chip_config(config_dir() + "trax.json",
                                        {"tms=4", "memory.l1d.banks=4", "timing.mode=precise",
                                         "tm.pipelines.reconfigure_cycles=9", "energy.fp_mul_nj=0.5"});
  EXPECT_EQ(c.tms, 4u);
  EXPECT_EQ(c.l1d.banks, 4u);
  EXPECT_EQ(c.timing.mode, transport::TimingMode::kPrecise);
  EXPECT_EQ(c.tm.pipelines.reconfigure_cycles, 9u);
  EXPECT_EQ(c.energy.fp_mul_nj, 0.5);
  const nlohmann::json j = to_json(c);
  EXPECT_EQ(j["memory"]["l1d"]["banks"], 4);
  EXPECT_EQ(j["timing"]["mode"], "precise");
  EXPECT_EQ(j["tms"], 4);
}

TEST(ChipConfig, ErrorsNameTheFieldAndTheProblem) {
  const std::string trax = config_dir() + "trax.json";
  EXPECT_NE(error_of(trax, {"tms=0"}).find("tms"), std::string::npos);
  EXPECT_NE(error_of(trax, {"memory.l1d.size_bytes=3000"}).find("power of two"), std::string::npos);
  EXPECT_NE(error_of(trax, {"memory.l2.sizee=1"}).find("unknown key 'memory.l2.sizee'"), std::string::npos);
  EXPECT_NE(error_of(trax, {"tms=\"many\""}).find("tms: expected a whole number"), std::string::npos);
  EXPECT_NE(error_of(trax, {"tms=-3"}).find("tms"), std::string::npos);
  EXPECT_NE(error_of(trax, {"tms=2.5"}).find("tms"), std::string::npos);
  EXPECT_NE(error_of(trax, {"timing.mode=fast"}).find("timing.mode"), std::string::npos);
  EXPECT_NE(error_of(trax, {"design.streams=1"}).find("design.streams: expected true or false"), std::string::npos);
  EXPECT_NE(error_of(trax, {"noequals"}).find("key=value"), std::string::npos);
  // A stream memory too small for one ray per TP (9914 rays in 512 KB, 16384 TPs).
  const std::string e = error_of(config_dir() + "strata-streams.json",
                                 {"memory.stream.size_bytes=524288", "tms=256", "tps_per_tm=64"});
  EXPECT_NE(e.find("memory.stream.size_bytes"), std::string::npos) << e;
  EXPECT_NE(e.find("fewer than one per TP"), std::string::npos) << e;
}

TEST(ChipConfig, SampledTimingWindowsMustFit) {
  const std::string trax = config_dir() + "trax.json";
  const ChipConfig ok = load_chip_config(trax, {"timing.mode=sampled"});
  EXPECT_EQ(ok.timing.mode, transport::TimingMode::kSampled);
  EXPECT_EQ(to_json(ok)["timing"]["mode"], "sampled");
  // The measured part of a detailed window must hold at least one quantum.
  std::string e = error_of(trax, {"timing.mode=sampled", "timing.sample_detail_cycles=2000",
                                  "timing.sample_warmup_cycles=1500"});
  EXPECT_NE(e.find("timing.sample_detail_cycles"), std::string::npos) << e;
  e = error_of(trax, {"timing.mode=sampled", "timing.sample_period_cycles=20000"});
  EXPECT_NE(e.find("timing.sample_period_cycles"), std::string::npos) << e;
  // Other modes ignore the sampling fields.
  EXPECT_EQ(error_of(trax, {"timing.sample_period_cycles=20000"}), "");
}

// Values that used to hang, wrap or fail only mid-simulation: each is refused up front,
// naming the field (issue: hostile input, rows 3, 4, 10, 11).
TEST(ChipConfig, OutOfRangeValuesAreRefusedNamingTheField) {
  const std::string trax = config_dir() + "trax.json";
  const std::string pipelines = config_dir() + "strata-pipelines.json";
  const struct {
    std::string file;
    std::string set;
    std::string expected;
  } cases[] = {
      // A 32-bit sum wrapped: warm-up 4294967000 + quantum 1000 passed as 704.
      {trax, "timing.sample_warmup_cycles=4294967000", "timing.sample_detail_cycles: must hold the warm-up"},
      {trax, "memory.l1d.calendar_horizon_cycles=4294967295", "l1d.calendar_horizon_cycles: must be at most 1048576 cycles"},
      {trax, "memory.l2.calendar_horizon_cycles=2147483648", "l2.calendar_horizon_cycles: must be at most 1048576 cycles"},
      {trax, "memory.dram.latency_cycles=4294967295", "dram.latency_cycles: must be at most 65536 cycles"},
      {trax, "memory.l2.hit_latency_cycles=100000", "l2.hit_latency_cycles: must be at most 65536 cycles"},
      {trax, "memory.interconnect.hop_latency_cycles=4294967295", "hop_latency_cycles: must be at most 65536"},
      {trax, "tm.xu.fp_div.latency=4294967295", "xu.fp_div.latency must be at most 65536 cycles"},
      {pipelines, "tm.pipelines.triangle.latency=4294967295", "pipelines.triangle.latency must be at most 65536"},
      {pipelines, "tm.pipelines.triangle.latency=1000", "pipelines.triangle.latency must be at most a sixteenth"},
      {trax, "timing.quantum_cycles=4294967295", "timing.quantum_cycles: must be 1..65536"},
      {trax, "memory.l2.line_bytes=32", "memory.l1d.line_bytes: must be at most memory.l2.line_bytes (32)"},
      {trax, "memory.l1i.line_bytes=1", "l1i.line_bytes: must be at least 16"},
      {trax, "energy.fp_mul_nj=1e308", "energies must be 0..1e6 nJ"},
      {trax, "memory.dram.access_energy_nj=1e308", "dram.access_energy_nj: must be 0..1e6 nJ"},
      // Issue 39 F12: a tiny value is printed as given, not as "0.000000" (0 is allowed).
      {trax, "timing.sample_target_error=1e-12", "relative half-width in [0.001, 0.5], got 1e-12"},
      {trax, "energy.fp_add_nj=-1e-09", "fp_add_nj: energies must be 0..1e6 nJ per operation, got -1e-09"},
      // Issue 39: a clock so slow that SystemC's picosecond time wrapped within the frame.
      {trax, "clock_ghz=1e-12", "clock_ghz: must be in [0.001, 100] GHz"},
      {trax, "clock_ghz=0.000999", "got 0.000999"},
  };
  for (const auto& c : cases) {
    const std::string e = error_of(c.file, {"timing.mode=sampled", c.set});
    EXPECT_NE(e.find(c.expected), std::string::npos) << c.set << " gave: " << e;
  }
}

// Found by fuzz_chip_config: a bare-word value that is not UTF-8 made the error message's JSON
// dump throw nlohmann's type_error (std::terminate in the fuzzer); as a string field's value it
// would have made the config's JSON echo throw later. Now it is a ConfigError naming the field.
TEST(ChipConfig, AnOverrideThatIsNotUtf8IsRefusedNamingTheField) {
  const std::string trax = config_dir() + "trax.json";
  for (const std::string set : {"tms=4\xb9", "design.name=x\xff" "y", "timing.sample_target_stats=x\xff" "y"}) {
    const std::string e = error_of(trax, {set});
    EXPECT_NE(e.find(set.substr(0, set.find('=')) + ": the value is not valid UTF-8"), std::string::npos) << e;
  }
  // Valid UTF-8 in a string field is kept as given (the statistics' names are checked later).
  EXPECT_EQ(load_chip_config(trax, {"timing.sample_target_stats=caf\xc3\xa9"}).timing.sample_target_stats,
            "caf\xc3\xa9");
}

// memory.dram.model picks the DRAM model; its banked timings are checked against the
// standard's rules only when the banked model is chosen, and errors name the field.
TEST(ChipConfig, DramModelIsChannelByDefaultAndBankedOnRequest) {
  const std::string trax = config_dir() + "trax.json";
  EXPECT_EQ(load_chip_config(trax, {}).dram.model, memory::DramModel::kChannel);
  const ChipConfig banked = load_chip_config(trax, {"memory.dram.model=banked", "memory.dram.banked.row_policy=closed"});
  EXPECT_EQ(banked.dram.model, memory::DramModel::kBanked);
  EXPECT_EQ(banked.dram.banked.row_policy, memory::RowPolicy::kClosed);
  std::string e = error_of(trax, {"memory.dram.model=hbm"});
  EXPECT_NE(e.find("memory.dram.model: expected one of channel, banked"), std::string::npos) << e;
  e = error_of(trax, {"memory.dram.model=banked", "memory.dram.banked.t_rc_ns=39"});
  EXPECT_NE(e.find("memory.dram.banked.t_rc_ns: must be at least t_ras_ns + t_rp_ns (40 ns)"), std::string::npos) << e;
  EXPECT_EQ(error_of(trax, {"memory.dram.banked.t_rc_ns=39"}), "");  // the channel model ignores it
}

TEST(ChipConfig, AFolderAsTheConfigIsNamed) {
  const std::string e = error_of(config_dir(), {});
  EXPECT_NE(e.find("cannot open config file: not a regular file"), std::string::npos) << e;
}

TEST(ChipConfig, BadFilesAreNamed) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string bad_json = (dir / "strata-bad-config.json").string();
  std::ofstream(bad_json) << "{ \"tms\": 4, ";
  EXPECT_NE(error_of(bad_json, {}).find("strata-bad-config.json: not valid JSON"), std::string::npos);
  const std::string typo = (dir / "strata-typo-config.json").string();
  std::ofstream(typo) << R"({"memory": {"l1d": {"size_byte": 1024}}})";
  const std::string e = error_of(typo, {});
  EXPECT_NE(e.find("strata-typo-config.json"), std::string::npos) << e;
  EXPECT_NE(e.find("memory.l1d.size_byte"), std::string::npos) << e;
  EXPECT_NE(error_of((dir / "no-such-config.json").string(), {}).find("cannot open"), std::string::npos);
  std::filesystem::remove(bad_json);
  std::filesystem::remove(typo);
}

// Issue 39 F6: 100,000 levels of nesting crashed with SIGSEGV (the binder's recursion, the error
// message's dump), and deep objects took 30 s first (a path string per level). The parse stops
// at the limit, naming the file and the limit, at once.
TEST(ChipConfig, NestingBeyondTheLimitIsRefusedNamingTheFileAtOnce) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string arrays = (dir / "strata-deep-arrays.json").string();
  const std::string objects = (dir / "strata-deep-objects.json").string();
  const int depth = 100000;
  std::ofstream(arrays) << "{\"tms\": " << std::string(depth, '[') << std::string(depth, ']') << "}";
  {
    std::ofstream out(objects);
    for (int i = 0; i < depth; ++i) out << "{\"a\": ";
    out << "1" << std::string(depth, '}');
  }
  for (const std::string& file : {arrays, objects}) {
    const auto t0 = std::chrono::steady_clock::now();
    const std::string e = error_of(file, {});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_NE(e.find(file + ": nested deeper than 64 levels"), std::string::npos) << e;
    EXPECT_LT(seconds, 5.0) << file;  // milliseconds: it reads no further than level 65
  }
  // At the limit a document still parses (and is then checked as usual: here, an unknown key).
  const std::string at_limit = (dir / "strata-deep-64.json").string();
  {
    std::ofstream out(at_limit);
    for (int i = 0; i < 64; ++i) out << "{\"a\": ";
    out << "1" << std::string(64, '}');
  }
  EXPECT_NE(error_of(at_limit, {}).find("unknown key 'a.a.a"), std::string::npos) << error_of(at_limit, {});
  // A --set value too: it was dumped, recursively, into the type error.
  const std::string set = "tms=" + std::string(60000, '[') + std::string(60000, ']');
  EXPECT_NE(error_of(config_dir() + "trax.json", {set}).find("--set tms: nested deeper than 64 levels"),
            std::string::npos);
  for (const std::string& f : {arrays, objects, at_limit}) std::filesystem::remove(f);
}

// Issue 39: a repeated key was accepted, the last one winning; now it is refused, naming the
// key by its path and the file.
TEST(ChipConfig, ADuplicateKeyIsRefusedNamingKeyAndFile) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string file = (dir / "strata-duplicate-key.json").string();
  std::ofstream(file) << R"({"tms": 4, "memory": {"l2": {"banks": 8, "size_bytes": 1048576, "banks": 16}}})";
  const std::string e = error_of(file, {});
  EXPECT_NE(e.find(file + ": duplicate key 'memory.l2.banks'"), std::string::npos) << e;
  std::ofstream(file) << R"({"tms": 4, "tms": 4})";
  EXPECT_NE(error_of(file, {}).find("duplicate key 'tms'"), std::string::npos) << error_of(file, {});
  // The same key in two different objects is no repetition.
  std::ofstream(file) << R"({"tm": {"xu": {"fp_mul": {"count": 8}, "fp_add": {"count": 8}}}})";
  EXPECT_EQ(error_of(file, {}), "");
  std::filesystem::remove(file);
}

// Issue 39: a syntax error said only "not valid JSON"; now it says where.
TEST(ChipConfig, ASyntaxErrorGivesFileLineAndColumn) {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string file = (dir / "strata-syntax-error.json").string();
  std::ofstream(file) << "{\n  \"tms\": 4,\n  \"tps_per_tm\": 4,,\n}\n";
  const std::string e = error_of(file, {});
  EXPECT_NE(e.find(file + ": not valid JSON at line 3, column 19"), std::string::npos) << e;
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace strata::chip
