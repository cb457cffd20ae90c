#include "plot/draw/nice_scale.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace saasgaps::plot {

int Scale::intervals() const { return static_cast<int>(std::lround((hi - lo) / step)); }

std::vector<double> Scale::values() const {
  std::vector<double> v;
  const int n = intervals();
  for (int k = 0; k <= n; ++k) {
    const double value = lo + k * step;
    // An exact zero, not 1e-13, where the scale crosses it.
    v.push_back(std::abs(value) < 1e-9 * step ? 0.0 : value);
  }
  return v;
}

bool is_uniform(double min, double max) {
  const double spread = std::abs(max - min);
  return spread <= 1e-5 * std::max(std::abs(min), std::abs(max)) || spread < 1e-300;
}

Scale nice_scale(double min, double max, int max_intervals, std::span<const double> mantissas) {
  if (!std::isfinite(min) || !std::isfinite(max)) throw std::invalid_argument("nice_scale: non-finite range");
  if (min > max) std::swap(min, max);
  max_intervals = std::max(1, max_intervals);
  if (is_uniform(min, max)) {
    const double magnitude = std::max(std::abs(min), std::abs(max));
    // A uniform value: one interval of a round width around it.
    const double half = magnitude > 0.0 ? std::pow(10.0, std::floor(std::log10(magnitude)) - 2.0) : 0.5;
    return {min - half, max + half, max + half - (min - half)};
  }
  // Start one decade below the step that would give max_intervals intervals and walk up.
  const double rough = (max - min) / max_intervals;
  double decade = std::pow(10.0, std::floor(std::log10(rough)) - 1.0);
  for (int guard = 0; guard < 8; ++guard, decade *= 10.0) {
    for (const double m : mantissas) {
      const double step = m * decade;
      const double lo = std::floor(min / step + 1e-9) * step;
      const double hi = std::ceil(max / step - 1e-9) * step;
      if (std::lround((hi - lo) / step) <= max_intervals) return {lo, hi, step};
    }
  }
  return {min, max, max - min};  // unreachable: the step grows past the range within two decades
}

}  // namespace saasgaps::plot
