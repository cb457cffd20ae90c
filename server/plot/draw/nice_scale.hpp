#pragma once
/// Round numbers for contour levels and axis ticks: lo, lo + step, .., hi with step = m * 10^k, m from
/// a short list of "nice" mantissas, lo and hi multiples of step enclosing the data.

#include <span>
#include <vector>

namespace saasgaps::plot {

struct Scale {
  double lo = 0.0;
  double hi = 1.0;
  double step = 1.0;
  int intervals() const;
  /// lo, lo + step, .., hi (intervals() + 1 values).
  std::vector<double> values() const;
};

/// Mantissas for contour levels: fine enough to get close to the requested band count.
inline constexpr double level_mantissas[] = {1.0, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0};
/// Mantissas for axis ticks: the classic 1-2-5 (and 2.5) series.
inline constexpr double tick_mantissas[] = {1.0, 2.0, 2.5, 5.0};

/// True when max - min is below 1e-5 of the values' magnitude: a uniform field up to round-off.
/// Contouring the round-off of a uniform stress (10005.8265 .. 10005.8295 psi) would show a pattern
/// that is not there.
bool is_uniform(double min, double max);

/// The finest nice scale enclosing [min, max] with at most max_intervals intervals (>= 1). A
/// uniform range (is_uniform) gets one interval around it. Non-finite input: std::invalid_argument.
Scale nice_scale(double min, double max, int max_intervals, std::span<const double> mantissas);

}  // namespace saasgaps::plot
