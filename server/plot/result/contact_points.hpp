#pragma once
/// The result's contact pairs (result `contact`) as the contact surfaces' plots read them: per pair
/// its points along side A with their position on the plot's x axis, and what the contact and
/// friction plots draw of each. Shared by contact_plot.cpp and friction_plot.cpp.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "plot/draw/chart.hpp"
#include "plot/result/gap_row.hpp"

namespace saasgaps::plot {

/// One contact pair's points, as plotted. A member a point lacks (or that is not a number) reads as
/// 0, a missing state as "": the plot shows what is there.
struct ContactPairCurve {
  std::string name;       ///< "A / B" (or "pair k" when the surfaces are not two names)
  double friction = 0.0;  ///< the pair's Coulomb mu (result `friction`, absent: 0, frictionless)
  std::vector<double> x;  ///< along the chosen axis (RowAxis)
  std::vector<double> r, z, pressure, gap, shear, slip;
  std::vector<std::string> state;
};

/// Every pair of the result's `contact`, in order; x measures along side A as `along` says: index
/// (1, 2, .. along A), position (arc length along A from its first point), r or z.
std::vector<ContactPairCurve> contact_pair_curves(const nlohmann::json& result, RowAxis along);

/// The x axis of a contact surfaces' plot over [low, high] for `along` (titles "point along side
/// A", "arc length along side A", "r", "z" with the length unit).
Axis contact_x_axis(double low, double high, RowAxis along, const UnitNames& units);

/// What a plot's header says of the run: the result's title, status and iterations (absent: "", ""
/// and 0).
struct RunFacts {
  std::string title, status;
  int iterations = 0;
};
RunFacts run_facts(const nlohmann::json& result);

/// The result's unit names (result `units`; absent: none).
UnitNames result_units(const nlohmann::json& result);

/// The colour of the k-th pair (cycling through six).
Rgb pair_color(std::size_t k);

/// The note "ticks <panel>: value@px value@px ..": where each y tick of the chart sits on the image.
std::string y_tick_note(const char* panel, const Chart& chart);

}  // namespace saasgaps::plot
