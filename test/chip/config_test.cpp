// Design configs: the three shipped files load; every field can be overridden; bad files,
// unknown keys, wrong types and impossible values are errors that name the field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "model/chip/chip_config.h"

namespace strata::chip {
namespace {

std::string config_dir() { return std::string(STRATA_SOURCE_DIR) + "/sim/configs/"; }

std::string error_of(const std::string& file, const std::vector<std::string>& overrides) {
  try {
    load_chip_config(file, overrides);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

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

}  // namespace
}  // namespace strata::chip
