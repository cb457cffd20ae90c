#pragma once
/// What the transient restart tests share besides the state round trip (state_round_trip.hpp):
/// the checks that a resumed heat conduction run is the uninterrupted one to the last digit.

#include <gtest/gtest.h>

#include <vector>

#include "solution.hpp"
#include "support/state_round_trip.hpp"
#include "thermal_record.hpp"

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

}  // namespace saasgaps::testing
