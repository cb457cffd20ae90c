#pragma once
/// A figure as the README or docs/ quote it, pinned to the digits quoted: `quoted` is the text as
/// printed ("6977", "0.00939", "-9520.1"), and the value must round to it, i.e.
///   |actual - quoted| <= half a unit of its last digit (plus 1e-12 of it for the decimal's round-off).
/// So a quoted figure holds exactly as long as the docs stay true, and fails as soon as they do not.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace saasgaps::testing {

/// Half a unit of the last digit of a decimal number written without an exponent.
inline double half_last_digit(const std::string& quoted) {
  const std::size_t point = quoted.find('.');
  const int decimals = point == std::string::npos ? 0 : static_cast<int>(quoted.size() - point - 1);
  return 0.5 * std::pow(10.0, -decimals);
}

/// gtest assertion: `actual` rounds to `quoted` at the digits given.
inline ::testing::AssertionResult rounds_to(double actual, const std::string& quoted) {
  const double value = std::stod(quoted);
  const double allowed = half_last_digit(quoted) + 1e-12 * std::abs(value);
  if (std::abs(actual - value) <= allowed) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << actual << " does not round to the quoted " << quoted << " (off by "
                                       << actual - value << ", allowed " << allowed << ")";
}

}  // namespace saasgaps::testing
