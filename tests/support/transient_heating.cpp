#include "support/transient_heating.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "support/examples.hpp"

namespace saasgaps::testing {

nlohmann::json transient_heating(const std::string& name, const TransientHeating& heating) {
  nlohmann::json m = example_document(name);
  std::map<int, double> radius_of;
  for (const auto& n : m["nodes"]) radius_of[n["id"].get<int>()] = std::hypot(n["r"].get<double>(), n["z"].get<double>());
  // Sides of solid elements, counted: a side of exactly one element is on the boundary.
  std::map<std::pair<int, int>, int> sides;
  double inner = std::numeric_limits<double>::infinity();
  double outer = 0.0;
  for (const auto& e : m["elements"]) {
    const std::vector<int> nodes = e["nodes"].get<std::vector<int>>();
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const int a = nodes[i];
      const int b = nodes[(i + 1) % nodes.size()];
      if (a == b) continue;  // a degenerate (triangular) quadrilateral's collapsed side
      ++sides[{std::min(a, b), std::max(a, b)}];
      inner = std::min(inner, radius_of[a]);
      outer = std::max(outer, radius_of[a]);
    }
  }
  // Generated meshes place their nodes to about 1e-9: nodes that close to the least radius are on it.
  const auto on_inner = [&](int node) { return radius_of[node] - inner <= 1.0e-7 * outer; };
  nlohmann::json edges = nlohmann::json::array();
  for (const auto& [side, count] : sides) {
    if (count == 1 && on_inner(side.first) && on_inner(side.second)) edges.push_back({side.first, side.second});
  }
  m["loads"].erase("temperatures");
  for (auto& material : m["materials"]) {
    material["density"] = 1.0;
    if (heating.yield_stress > 0.0) {
      material["plasticity"] = {{"yield_stress", heating.yield_stress}, {"hardening_ratio", 1.0 / 3.0}};
    }
    for (auto& row : material["table"]) {
      row["k"] = 1.0;
      row["c"] = 1.0;
      if (heating.alpha != 0.0) row["alpha"] = heating.alpha;
    }
  }
  const double end = heating.output_times.back();
  m["thermal"] = {{"type", "transient"},
                  {"boundary", nlohmann::json::array({{{"edges", edges}, {"temperature", heating.hot}}})},
                  {"initial_temperature", 0.0},
                  {"time_step", heating.time_step},
                  {"end_time", end},
                  {"output_times", heating.output_times}};
  return m;
}

}  // namespace saasgaps::testing
