// The TM config: defaults from ARCHITECTURE.md, and errors that name the bad field.
#include "model/tm/tm_config.h"
#include "model/tm/xu_crossbar.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace strata::tm {
namespace {

TEST(XuConfig, DefaultsFollowTheArchitecture) {
  const TmConfig c;
  EXPECT_NO_THROW(c.validate());
  EXPECT_EQ(c.tps, 32u);
  EXPECT_EQ(c.xu.fp_mul.count, 8u);
  EXPECT_EQ(c.xu.fp_mul.latency, 2u);
  EXPECT_TRUE(c.xu.fp_mul.pipelined);
  EXPECT_EQ(c.xu.fp_add.count, 8u);
  EXPECT_EQ(c.xu.fp_add.latency, 2u);
  EXPECT_EQ(c.xu.fp_cmp.latency, 1u);
  EXPECT_EQ(c.xu.fp_div.latency, 16u);
  EXPECT_FALSE(c.xu.fp_div.pipelined);
  EXPECT_EQ(c.pipelines.box.multipliers, 6u);
  EXPECT_EQ(c.pipelines.box.adders, 6u);
  EXPECT_EQ(c.pipelines.box.initiation_interval, 1u);
  EXPECT_EQ(c.pipelines.box.latency, 8u);
  EXPECT_EQ(c.pipelines.triangle.multipliers, 4u);
  EXPECT_EQ(c.pipelines.triangle.adders, 2u);
  EXPECT_EQ(c.pipelines.triangle.initiation_interval, 18u);
  EXPECT_EQ(c.pipelines.triangle.latency, 31u);
  EXPECT_EQ(c.pipelines.triangle.issue_width, 2u);
}

void expect_rejected(const std::function<void(TmConfig&)>& change, const std::string& field) {
  TmConfig c;
  change(c);
  try {
    c.validate();
    FAIL() << field << ": accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(field));
  }
}

TEST(XuConfig, ImpossibleValuesAreRejectedByName) {
  expect_rejected([](TmConfig& c) { c.tps = 0; }, "tps");
  expect_rejected([](TmConfig& c) { c.xu.fp_mul.count = 0; }, "xu.fp_mul.count");
  expect_rejected([](TmConfig& c) { c.xu.fp_add.latency = 0; }, "xu.fp_add.latency");
  expect_rejected([](TmConfig& c) { c.xu.fp_div.latency = 0; }, "xu.fp_div.latency");
  expect_rejected([](TmConfig& c) { c.xu.int_mul.count = 0; }, "xu.int_mul.count");
  expect_rejected([](TmConfig& c) { c.tp.int_alu_latency = 0; }, "tp.int_alu_latency");
  expect_rejected([](TmConfig& c) { c.pipelines.box.multipliers = 8; }, "pipelines.box.multipliers");
  expect_rejected([](TmConfig& c) { c.pipelines.box.adders = 9; }, "pipelines.box.adders");
  expect_rejected([](TmConfig& c) { c.pipelines.box.latency = 0; }, "pipelines.box.latency");
  expect_rejected([](TmConfig& c) { c.pipelines.triangle.initiation_interval = 0; },
                  "pipelines.triangle.initiation_interval");
  expect_rejected([](TmConfig& c) { c.pipelines.triangle.issue_width = 0; }, "pipelines.triangle.issue_width");
  expect_rejected([](TmConfig& c) { c.pipelines.triangle_divide_latency = 0; },
                  "pipelines.triangle_divide_latency");
  expect_rejected([](TmConfig& c) { c.xu_history_cycles = 0; }, "xu_history_cycles");
  expect_rejected([](TmConfig& c) { c.xu_history_cycles = c.xu_horizon_cycles / 4 + 1; }, "xu_history_cycles");
  expect_rejected([](TmConfig& c) { c.xu_horizon_cycles = 32; }, "xu_horizon_cycles");
  // Fewer units make the default pipelines impossible.
  expect_rejected([](TmConfig& c) { c.xu.fp_mul.count = 6; }, "pipelines.box.multipliers");
}

TEST(XuConfig, CrossbarRefusesAnInvalidConfig) {
  TmConfig c;
  c.pipelines.triangle.multipliers = 8;
  EXPECT_THROW(XuCrossbar{c}, std::invalid_argument);
}

TEST(XuConfig, ZeroReconfigureCostIsAllowed) {
  TmConfig c;
  c.pipelines.reconfigure_cycles = 0;
  EXPECT_NO_THROW(c.validate());
}

}  // namespace
}  // namespace strata::tm
