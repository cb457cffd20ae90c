#include "plot/draw/band_levels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "plot/draw/nice_scale.hpp"

namespace saasgaps::plot {

LevelRule level_rule(const std::string& name) {
  if (name == "quantile") return LevelRule::quantile;
  if (name == "even") return LevelRule::even;
  throw std::invalid_argument("band levels are 'quantile' or 'even', not '" + name + "'");
}

BandLevels band_levels(const std::vector<double>& values, const std::vector<double>& weights, int max_bands,
                       LevelRule rule) {
  max_bands = std::max(1, max_bands);
  std::vector<std::size_t> order;
  double total = 0.0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (std::isfinite(values[i])) {
      order.push_back(i);
      total += weights[i];
    }
  }
  if (order.empty()) throw std::invalid_argument("the field has no finite values");
  const auto [lo, hi] = std::minmax_element(order.begin(), order.end(),
                                            [&values](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  const double low = values[*lo], high = values[*hi];
  if (is_uniform(low, high) || rule == LevelRule::even) {
    const Scale s = nice_scale(low, high, max_bands, level_mantissas);
    return {s.values(), s.step, is_uniform(low, high)};
  }

  // The quantiles q_k, k = 0 .. n - 1, at cumulative weight k/(n - 1) of the total (q_0 = low,
  // q_(n-1) = high); those that coincide (a field mostly at a few values) are one.
  std::sort(order.begin(), order.end(), [&values](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> q{low};
  double below = 0.0;
  std::size_t at = 0;
  for (int k = 1; k + 1 < max_bands; ++k) {
    const double target = total * k / (max_bands - 1);
    while (at + 1 < order.size() && below + weights[order[at]] < target) below += weights[order[at++]];
    q.push_back(values[order[at]]);
  }
  q.push_back(high);
  // Quantiles closer than quantile_resolution of the field's magnitude are one: a band that narrow
  // shows round-off or discretisation noise, not a pattern (the shrink-fit rings' out-of-plane
  // stress, -91530 in one ring and 6552.8 .. 6555.8 in the other, used to get eight bands of 0.4 psi).
  const double min_gap = quantile_resolution * std::max(std::abs(low), std::abs(high));
  std::vector<double> kept{q.front()};
  for (std::size_t k = 1; k + 1 < q.size(); ++k) {
    if (q[k] - kept.back() >= min_gap) kept.push_back(q[k]);
  }
  if (kept.size() > 1 && high - kept.back() < min_gap) kept.pop_back();
  kept.push_back(high);
  q = std::move(kept);
  // A level midway between neighbouring quantiles: at most n bands, the end ones half as large (the
  // extremes stand out), and a field that jumps (two rings at two temperatures) gets its level
  // between the two values, not on one of them. Each level is rounded to a step of about a tenth
  // of the gap it sits in: two or three significant digits of what tells the bands apart, so that
  // a ring varying 6552 .. 6556 next to one at -91530 keeps its bands; rounding never leaves the gap.
  const auto round_step = [](double width) { return nice_scale(0.0, width, 10, tick_mantissas).step; };
  const double first_step = round_step(q[1] - q[0]), last_step = round_step(q[q.size() - 1] - q[q.size() - 2]);
  BandLevels result{{std::floor(low / first_step + 1e-9) * first_step}, std::min(first_step, last_step), false};
  for (std::size_t j = 0; j + 1 < q.size(); ++j) {
    const double step = round_step(q[j + 1] - q[j]);
    result.levels.push_back(std::round((q[j] + q[j + 1]) / 2.0 / step) * step);
    result.label_step = std::min(result.label_step, step);
  }
  result.levels.push_back(std::ceil(high / last_step - 1e-9) * last_step);
  for (double& l : result.levels) {
    if (std::abs(l) < 1e-9 * result.label_step) l = 0.0;  // an exact zero, not 1e-13
  }
  return result;
}

}  // namespace saasgaps::plot
