/// The history row's friction columns (io/history_json.hpp): written only for a run with friction,
/// read back with defaults, and kept exactly through the text the service stores and the CBOR of
/// restart states and the worker protocol.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/results/history_json.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;

IterationRecord exact_row() {
  IterationRecord r;
  r.iteration = 4;
  r.step = 2;
  r.increment = 3;
  r.closed_gaps = 0;
  r.contact_pairs = 17;
  r.complementarity = 2.5e-15;
  r.active_set_iterations = 3;
  r.seconds = 0.125;
  return r;
}

IterationRecord friction_row() {
  IterationRecord r = exact_row();
  r.stick_points = 11;
  r.slip_points = 6;
  r.friction_residual = 3.0000000000000004e-13;
  return r;
}

TEST(HistoryJson, FrictionlessRowHasNoFrictionColumns) {
  const json row = json::parse(history_row_text(exact_row()));
  for (const char* key : {"stick_points", "slip_points", "friction_residual"}) EXPECT_FALSE(row.contains(key)) << key;
  EXPECT_FALSE(history_row_json(exact_row()).contains("stick_points"));
  EXPECT_FALSE(has_friction_columns(exact_row()));
}

TEST(HistoryJson, FrictionRowCarriesItsCountsAndResidualInAlphabeticalPlace) {
  const std::string text = history_row_text(friction_row());
  const json row = json::parse(text);
  EXPECT_EQ(row.at("stick_points"), 11);
  EXPECT_EQ(row.at("slip_points"), 6);
  EXPECT_EQ(row.at("friction_residual").get<double>(), 3.0000000000000004e-13);
  // Members in alphabetical order, as the tree (history_row_json) dumps them.
  EXPECT_EQ(json::parse(text).dump(), history_row_json(friction_row()).dump());
  EXPECT_LT(text.find("\"extrapolated\""), text.find("\"friction_residual\""));
  EXPECT_LT(text.find("\"friction_residual\""), text.find("\"gap_closures\""));
  EXPECT_LT(text.find("\"seconds\""), text.find("\"slip_points\""));
  EXPECT_LT(text.find("\"slip_points\""), text.find("\"step\""));
  EXPECT_LT(text.find("\"step\""), text.find("\"stick_points\""));
  EXPECT_LT(text.find("\"stick_points\""), text.find("\"tensile_modulus\""));
}

TEST(HistoryJson, EitherCountOrTheResidualAloneMakesAFrictionRow) {
  IterationRecord slipping = exact_row();
  slipping.slip_points = 1;
  EXPECT_TRUE(history_row_json(slipping).contains("stick_points"));
  IterationRecord sticking = exact_row();
  sticking.stick_points = 1;
  EXPECT_TRUE(json::parse(history_row_text(sticking)).contains("friction_residual"));
  IterationRecord residual_only = exact_row();
  residual_only.friction_residual = 0.5;
  EXPECT_EQ(json::parse(history_row_text(residual_only)).at("slip_points"), 0);
}

TEST(HistoryJson, FrictionColumnsRoundTripThroughTextAndCbor) {
  const IterationRecord row = friction_row();
  // The service stores the text; the watch command and the dashboard read it back.
  const IterationRecord from_text = history_row_from_json(json::parse(history_row_text(row)));
  EXPECT_TRUE(from_text.same_numbers(row));
  EXPECT_EQ(from_text.stick_points, 11);
  EXPECT_EQ(from_text.slip_points, 6);
  EXPECT_EQ(from_text.friction_residual, row.friction_residual);
  // Restart states and the worker protocol carry the tree as CBOR.
  const std::vector<std::uint8_t> cbor = json::to_cbor(history_row_json(row));
  const IterationRecord from_cbor = history_row_from_json(json::from_cbor(cbor));
  EXPECT_TRUE(from_cbor.same_numbers(row));
  EXPECT_EQ(from_cbor.friction_residual, row.friction_residual);
}

TEST(HistoryJson, RowsWithoutFrictionColumnsReadAsZero) {
  // A row written before friction existed (or by a frictionless run) reads as 0, 0, 0.
  const IterationRecord r = history_row_from_json(json::parse(history_row_text(exact_row())));
  EXPECT_EQ(r.stick_points, 0);
  EXPECT_EQ(r.slip_points, 0);
  EXPECT_EQ(r.friction_residual, 0.0);
  EXPECT_TRUE(r.same_numbers(exact_row()));
}

TEST(HistoryJson, IncrementEndsCarrySetReactionsAndPairForcesThroughTextAndTree) {
  IterationRecord row = friction_row();
  row.set_reactions = {{"pushed", 0.25, 1474.3}, {"outer_support", -0.25, -1474.3}};
  row.pair_forces = {{{"outer_bore", "inner_outside"}, 1.5, -1474.3}};
  const std::string text = history_row_text(row);
  EXPECT_EQ(json::parse(text).dump(), history_row_json(row).dump());  // alphabetical, as the tree
  EXPECT_NE(text.find(R"("set_reactions":[{"fr":0.25,"fz":1474.3,"set":"pushed"})"), std::string::npos) << text;
  EXPECT_NE(text.find(R"("pair_forces":[{"fr":1.5,"fz":-1474.3,"surfaces":["outer_bore","inner_outside"]}])"),
            std::string::npos)
      << text;
  const IterationRecord back = history_row_from_json(json::parse(text));
  EXPECT_TRUE(back.same_numbers(row));
  // A row without them (not an increment's end, or no sets or pairs) writes neither.
  EXPECT_EQ(history_row_text(friction_row()).find("set_reactions"), std::string::npos);
  EXPECT_EQ(history_row_text(friction_row()).find("pair_forces"), std::string::npos);
  IterationRecord other = row;
  other.set_reactions[0].f_z += 1.0;
  EXPECT_FALSE(other.same_numbers(row));
}

}  // namespace
}  // namespace saasgaps::io
