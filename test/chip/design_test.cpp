// The design descriptor (model/chip/design.h): design.name selects a design and sets its
// mechanism flags, a flag that contradicts the design is refused naming the field, and every
// shipped config names a design whose kernels were built.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "config_support.h"
#include "model/chip/chip_config.h"
#include "model/chip/design.h"
#include "sim/iss_render.h"

namespace strata::chip {
namespace {

using test::config_dir;
using test::error_of;

TEST(Design, EveryShippedConfigNamesADesignWhoseKernelsWereBuilt) {
  for (const char* file : {"trax.json", "strata-streams.json", "strata-pipelines.json"}) {
    SCOPED_TRACE(file);
    const ChipConfig c = load_chip_config(config_dir() + file, {});
    const Design& d = design_named(c.design.name);
    EXPECT_EQ(c.design.streams, d.streams);
    EXPECT_EQ(c.design.pipelines, d.pipelines);
    for (const char* placement : {"compact", "on-chip", "dram"}) {
      const ChipConfig p = load_chip_config(config_dir() + file, {std::string("design.path_state=") + placement});
      EXPECT_TRUE(std::filesystem::exists(sim::default_kernel_elf(kernel_of(p.design)))) << kernel_of(p.design);
    }
  }
}

TEST(Design, TheNameSetsTheMechanismFlags) {
  const ChipConfig streams = load_chip_config(config_dir() + "trax.json", {"design.name=strata-streams"});
  EXPECT_TRUE(streams.design.streams);
  EXPECT_FALSE(streams.design.pipelines);
  EXPECT_EQ(kernel_of(streams.design), "streams_compact");
  const ChipConfig trax = load_chip_config(config_dir() + "strata-pipelines.json", {"design.name=trax-baseline"});
  EXPECT_FALSE(trax.design.streams);
  EXPECT_FALSE(trax.design.pipelines);
  EXPECT_EQ(kernel_of(trax.design), "baseline");  // the path state does not apply to TRaX
}

TEST(Design, AFlagThatContradictsTheDesignIsRefusedNamingTheField) {
  const std::string trax = config_dir() + "trax.json", pipes = config_dir() + "strata-pipelines.json";
  // No design has pipelines without streams: once the frame silently ran the baseline kernel.
  const std::string no_streams = error_of(pipes, {"design.streams=false"});
  EXPECT_EQ(no_streams.rfind("design.streams: false contradicts design.name=strata-streams-pipelines", 0), 0u)
      << no_streams;
  EXPECT_NE(no_streams.find("no design has design.streams=false and design.pipelines=true"), std::string::npos)
      << no_streams;
  // A combination another design has: the error names it.
  const std::string streams_on_trax = error_of(trax, {"design.streams=true"});
  EXPECT_NE(streams_on_trax.find("design.streams: true contradicts design.name=trax-baseline"), std::string::npos)
      << streams_on_trax;
  EXPECT_NE(streams_on_trax.find("is strata-streams)"), std::string::npos) << streams_on_trax;
  EXPECT_NE(error_of(pipes, {"design.pipelines=false"}).find("design.pipelines: false contradicts"), std::string::npos);
  // A flag set to what the design has is fine, before or after the name.
  EXPECT_EQ(error_of(trax, {"design.streams=true", "design.name=strata-streams"}), "");
  EXPECT_EQ(error_of(trax, {"design.name=strata-streams", "design.streams=true"}), "");
}

TEST(Design, AnUnknownNameIsRefusedListingTheDesigns) {
  const std::string e = error_of(config_dir() + "trax.json", {"design.name=strata-pipelines"});
  EXPECT_NE(e.find("design.name: expected one of trax-baseline, strata-streams, strata-streams-pipelines"),
            std::string::npos)
      << e;
  EXPECT_THROW(design_named("trax"), ConfigError);
  DesignConfig set_in_code;  // a config built in code is checked by finalize() too
  set_in_code.name = "x";
  ChipConfig c;
  c.design = set_in_code;
  try {
    c.finalize();
    ADD_FAILURE() << "an unknown design was accepted";
  } catch (const ConfigError& err) {
    EXPECT_NE(std::string(err.what()).find("design.name: unknown design \"x\""), std::string::npos) << err.what();
  }
}

}  // namespace
}  // namespace strata::chip
