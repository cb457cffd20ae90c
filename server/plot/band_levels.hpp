#pragma once
/// The levels between a contour plot's colour bands.
///
/// quantile (the default): the levels split the body into bands of about equal area. With n
/// bands, q_k is the value below which k/(n - 1) of the area lies (k = 0 .. n - 1; the nodal values
/// weighted by the area each node stands for, an equal share of each solid element around it), and
/// the levels sit midway between neighbouring q_k (and at the ends, rounded outwards): n - 2 bands
/// of equal area and two half bands holding the extremes. Each level is rounded to a round step of
/// about a tenth of the gap it sits in, so the colour bar reads 1250, not 1247.3. A peak at one
/// corner then gets one band and the rest of the body keeps the others: a ring whose stress varies
/// a little is not drawn in a single colour because another ring varies a lot. Quantiles that
/// coincide merge, so a field at two values gets two bands with a level between the values.
/// even: round, equally spaced levels enclosing the data (nice_scale), the classic picture in
/// which equal steps of colour are equal steps of value.
/// Either way the ends enclose the data, and a uniform field (is_uniform) gets one band.

#include <string>
#include <vector>

namespace saasgaps::plot {

enum class LevelRule { quantile, even };

/// "quantile" or "even"; anything else: std::invalid_argument.
LevelRule level_rule(const std::string& name);

struct BandLevels {
  std::vector<double> levels;  ///< increasing; bands = levels.size() - 1 >= 1
  double label_step = 1.0;     ///< the rounding step, for the labels' decimals
  bool uniform = false;
};

/// Levels for values[i] with weights[i] >= 0 (NaN values are skipped); at most max_bands bands.
/// No finite value: std::invalid_argument.
BandLevels band_levels(const std::vector<double>& values, const std::vector<double>& weights, int max_bands,
                       LevelRule rule);

}  // namespace saasgaps::plot
