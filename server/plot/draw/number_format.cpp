#include "plot/draw/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace saasgaps::plot {

namespace {

/// Fewest decimals d (0..6) for which x * 10^d is a whole number (x > 0).
int decimals_for(double x) {
  for (int d = 0; d < 6; ++d) {
    const double scaled = x * std::pow(10.0, d);
    if (std::abs(scaled - std::round(scaled)) < 1e-6 * scaled) return d;
  }
  return 6;
}

}  // namespace

TickFormat::TickFormat(double step, double magnitude) : step_(std::abs(step)) {
  magnitude = std::abs(magnitude);
  scientific_ = magnitude >= 1e6 || (magnitude > 0.0 && magnitude < 1e-3);
  if (step_ <= 0.0 || !std::isfinite(step_)) {
    decimals_ = 3;
  } else if (scientific_) {
    // The mantissa of the largest value carries the exponent; the step in units of that power.
    const double exponent = std::floor(std::log10(magnitude));
    decimals_ = decimals_for(step_ / std::pow(10.0, exponent));
  } else {
    decimals_ = decimals_for(step_);
  }
}

std::string TickFormat::operator()(double value) const {
  if (std::abs(value) < 1e-9 * step_ || value == 0.0) return "0";
  char text[64];
  std::snprintf(text, sizeof text, scientific_ ? "%.*e" : "%.*f", decimals_, value);
  return text;
}

std::string format_value(double value, int significant) {
  if (value == 0.0) return "0";
  if (!std::isfinite(value)) return std::isnan(value) ? "NaN" : (value > 0 ? "inf" : "-inf");
  char text[64];
  const double magnitude = std::abs(value);
  if (magnitude >= 1e-3 && magnitude < 1e6) {
    // Fixed notation; whole numbers keep all their digits (12519, not 1.252e+04).
    const int decimals = std::max(0, significant - 1 - static_cast<int>(std::floor(std::log10(magnitude))));
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    // Trailing zeros say nothing on their own: 50.0 -> 50, 1.250 -> 1.25.
    std::string fixed = text;
    if (fixed.find('.') != std::string::npos) {
      fixed.erase(fixed.find_last_not_of('0') + 1);
      if (fixed.back() == '.') fixed.pop_back();
    }
    return fixed;
  } else {
    std::snprintf(text, sizeof text, "%.*e", significant - 1, value);
  }
  return text;
}

}  // namespace saasgaps::plot
