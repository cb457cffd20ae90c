#include "io/json/value_rules.hpp"

#include <cmath>

namespace saasgaps::io {

bool contains(const Range& range, double v) {
  if (range.lower && (range.lower->inclusive ? v < range.lower->value : v <= range.lower->value)) return false;
  if (range.upper && (range.upper->inclusive ? v > range.upper->value : v >= range.upper->value)) return false;
  return true;
}

namespace {

/// Bounds are round numbers; write 0 rather than 0.0 so the rule reads like the documentation.
std::string format_bound(double v) {
  if (v == std::floor(v) && std::fabs(v) < 1e15) return std::to_string(static_cast<long long>(v));
  return format_number(v);
}

}  // namespace

std::string requirement(const Range& range, std::string_view name) {
  const auto op = [](const Bound& b) { return b.inclusive ? " <= " : " < "; };
  std::string text;
  if (range.lower && range.upper) {
    text = format_bound(range.lower->value) + op(*range.lower) + std::string(name) + op(*range.upper) +
           format_bound(range.upper->value);
  } else if (range.lower) {
    text = std::string(name) + (range.lower->inclusive ? " >= " : " > ") + format_bound(range.lower->value);
  } else if (range.upper) {
    text = std::string(name) + op(*range.upper) + format_bound(range.upper->value);
  }
  if (range.reason != nullptr) text += std::string(" (") + range.reason + ")";
  return text;
}

}  // namespace saasgaps::io
