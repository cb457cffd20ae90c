#pragma once
/// What the transient restart tests share besides the state round trip (state_round_trip.hpp):
/// the checks that a resumed heat conduction run is the uninterrupted one to the last digit.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "solver/state/solution.hpp"
#include "solver/state/thermal_record.hpp"
#include "solver/thermal/thermal_analysis.hpp"
#include "support/identical_solutions.hpp"
#include "support/state_recorder.hpp"
#include "support/state_round_trip.hpp"

namespace saasgaps::testing {

/// The same output times, temperature history, final temperatures and time steps.
inline void expect_same_thermal(const Solution& a, const Solution& b) {
  ASSERT_TRUE(a.thermal.has_value());
  ASSERT_TRUE(b.thermal.has_value());
  EXPECT_EQ(a.thermal->times, b.thermal->times);
  EXPECT_EQ(a.thermal->history, b.thermal->history);
  EXPECT_EQ(a.thermal->T, b.thermal->T);
  EXPECT_EQ(a.thermal->time_steps, b.thermal->time_steps);
}

/// The same thermal history rows, number for number.
inline void expect_same_rows(const std::vector<ThermalRecord>& a, const std::vector<ThermalRecord>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(a[i].same_numbers(b[i])) << "thermal row " << i + 1;
}

/// The run resumed from `state`, saved after iteration k, through every codec: the uninterrupted
/// run's solution, temperatures and thermal rows to the last digit, and its iteration rows after k.
inline void expect_resumes_to_the_last_digit(const Model& model, const RestartState& state, const std::string& digest,
                                             const Solution& uninterrupted, const StateRecorder& all, int k) {
  for (const std::string_view codec : state_codecs) {
    SCOPED_TRACE(codec);
    const RestartState from = through_codec(codec, state, digest);
    StateRecorder again;
    const Solution resumed = solve_with_heat(model, &again, &from);
    expect_identical(resumed, uninterrupted);
    expect_same_thermal(resumed, uninterrupted);
    expect_same_rows(again.thermal, all.thermal);
    // The resumed run reports only the iterations after k, equal to the uninterrupted run's.
    ASSERT_EQ(again.rows.size(), all.rows.size() - static_cast<std::size_t>(k));
    for (std::size_t i = 0; i < again.rows.size(); ++i) EXPECT_TRUE(again.rows[i].same_numbers(all.rows[k + i]));
  }
}

}  // namespace saasgaps::testing
