#pragma once
/// What the transient restart tests share: a restart state through each encoding a resume reads,
/// and the checks that a resumed heat conduction run is the uninterrupted one to the last digit.

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "io/state_codec.hpp"
#include "io/stored_state.hpp"
#include "restart_state.hpp"
#include "solution.hpp"
#include "thermal_record.hpp"

namespace saasgaps::testing {

/// The encodings a resume reads a state from: the JSON and CBOR restart states, the service's stored form.
constexpr std::array<std::string_view, 3> state_codecs{"json", "cbor", "stored"};

/// `state` encoded with `codec` (one of state_codecs) for the model of `digest`, and read back.
inline RestartState through_codec(std::string_view codec, const RestartState& state, const std::string& digest) {
  if (codec == "json") return io::state_from_json(io::state_to_json(state, digest), digest);
  if (codec == "cbor") return io::state_from_cbor(io::state_to_cbor(state, digest), digest);
  return io::decode_stored_state(io::encode_stored_state(state, digest), digest);
}

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
