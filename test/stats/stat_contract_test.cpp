// A statistics contract (model/stats/stat_contract.h) holds when every required path is
// registered with its unit, and names the owner, the path and the unit when it does not.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "model/stats/stat_contract.h"

namespace strata::stats {
namespace {

std::string failure(const Group& g, const std::vector<Requirement>& contract) {
  try {
    require_stats(g, "the model", contract);
  } catch (const std::logic_error& e) {
    return e.what();
  }
  return "";
}

struct Level {
  uint64_t bytes = 0, hits = 0;
  Group root{"dram", "A level."};
  Group by_data{"by_data", "By class."};
  Group channel{"channel", "One channel."};
  Level() {
    root.count("bytes", &bytes, Unit::kBytes, "Bytes.");
    by_data.count("hits", &hits, Unit::kCount, "Hits.");
    root.child(&by_data);
    channel.count("bytes", &bytes, Unit::kBytes, "Bytes.");
    root.instances("channels", {&channel}, "channel", "Per channel.");
  }
};

TEST(StatContract, HoldsWhenEveryPathIsThereWithItsUnit) {
  const Level l;
  EXPECT_EQ(failure(l.root, {{"bytes", Unit::kBytes}, {"by_data.hits", Unit::kCount}, {"by_data", Unit::kCount, true},
                             {"channels.bytes", Unit::kBytes}, {"channels", Unit::kCount, true}}),
            "");
}

TEST(StatContract, AMissingStatisticOrGroupIsNamedWithTheOwner) {
  const Level l;
  EXPECT_EQ(failure(l.root, {{"energy_nj", Unit::kNanojoules}}),
            "the model: its statistics (dram) lack energy_nj [nJ], which the chip reads");
  EXPECT_EQ(failure(l.root, {{"by_class.hits", Unit::kCount}}),
            "the model: its statistics (dram) lack by_class.hits, which the chip reads");
  EXPECT_EQ(failure(l.root, {{"banked", Unit::kCount, true}}),
            "the model: its statistics (dram) lack banked (a group), which the chip reads");
  // A statistic is not a group, and a group is not a statistic.
  EXPECT_NE(failure(l.root, {{"bytes", Unit::kCount, true}}), "");
  EXPECT_NE(failure(l.root, {{"by_data", Unit::kCount}}), "");
}

TEST(StatContract, AnotherUnitIsNamed) {
  const Level l;
  EXPECT_EQ(failure(l.root, {{"bytes", Unit::kCount}}),
            "the model: dram.bytes is in bytes, but the chip reads it in count");
}

}  // namespace
}  // namespace strata::stats
