#pragma once
/// The levels between a contour plot's colour bands.
///
/// even (the default): round, equally spaced levels enclosing the data (nice_scale), the classic
/// picture in which equal steps of colour are equal steps of value; a range that spans zero has a
/// level at zero, where the diverging colour map turns.
/// quantile (on request): the levels split the body into bands of about equal area. With n
/// bands, q_k is the value below which k/(n - 1) of the area lies (k = 0 .. n - 1; the nodal values
/// weighted by the area each node stands for, an equal share of each solid element around it), and
/// the levels sit midway between neighbouring q_k (and at the ends, rounded outwards): n - 2 bands
/// of equal area and two half bands holding the extremes. Each level is rounded to a round step of
/// about a tenth of the gap it sits in, so the colour bar reads 1250, not 1247.3. A peak at one
/// corner then gets one band and the rest of the body keeps the others. Quantiles closer than
/// quantile_resolution of the field's magnitude max(|min|, |max|) merge (so do those that coincide):
/// a ring whose stress is constant up to discretisation noise next to one at -91530 gets one band,
/// not eight bands of 0.4 psi; a field at two values gets two bands with a level between the values.
/// Either way the ends enclose the data, and a uniform field (is_uniform) gets one band.

#include <string>
#include <vector>

namespace saasgaps::plot {

enum class LevelRule { quantile, even };

/// Neighbouring quantiles closer than this share of the field's magnitude merge: differences that
/// small are round-off or discretisation noise (nice_scale.hpp's is_uniform calls a whole field
/// uniform at 1e-5).
inline constexpr double quantile_resolution = 1e-4;

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
