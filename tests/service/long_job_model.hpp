#pragma once
/// A model big enough that its iterations take noticeable time: an n x n plane-strain block cut at
/// mid height by a row of gap elements. The upper half is pressed down on the left quarter of its top
/// and pulled up on the right quarter, so it tilts: gaps close on the left and open on the right, and
/// the tensile schedule takes several iterations to relax the open ones.

#include <nlohmann/json.hpp>

namespace saasgaps::testing {

inline nlohmann::json tilted_block_document(int n) {
  using nlohmann::json;
  const int half = n / 2;
  const double h = 1.0 / n;
  const double gap = 0.01 * h;
  json nodes = json::array(), elements = json::array(), gaps = json::array(), constraints = json::array(),
       pressures = json::array();
  int next_node = 0, next_element = 0;
  // Node ids of a (n + 1) x (rows + 1) grid whose bottom row sits at z0.
  const auto grid = [&](int rows, double z0) {
    std::vector<std::vector<int>> id(static_cast<std::size_t>(rows + 1), std::vector<int>(static_cast<std::size_t>(n + 1)));
    for (int j = 0; j <= rows; ++j) {
      for (int i = 0; i <= n; ++i) {
        id[j][i] = ++next_node;
        nodes.push_back({{"id", next_node}, {"r", i * h}, {"z", z0 + j * h}});
      }
    }
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < n; ++i) {
        elements.push_back({{"id", ++next_element},
                            {"nodes", {id[j][i], id[j][i + 1], id[j + 1][i + 1], id[j + 1][i]}},
                            {"material", 1}});
      }
    }
    return id;
  };
  const auto lower = grid(half, 0.0);
  const auto upper = grid(n - half, half * h + gap);
  for (int i = 0; i < n; ++i) {
    gaps.push_back({{"id", ++next_element},
                    {"nodes", {lower[half][i], lower[half][i + 1], upper[0][i + 1], upper[0][i]}},
                    {"angle", 90.0}});
  }
  for (int i = 0; i <= n; ++i) constraints.push_back({{"node", lower[0][i]}, {"r", 0.0}, {"z", 0.0}});
  constraints.push_back({{"node", upper[n - half][0]}, {"r", 0.0}});
  for (int i = 0; i < n / 4; ++i) {
    pressures.push_back({{"nodes", {upper[n - half][i], upper[n - half][i + 1]}}, {"normal", 1000.0}});
    pressures.push_back({{"nodes", {upper[n - half][n - 1 - i], upper[n - half][n - i]}}, {"normal", -200.0}});
  }
  return {{"schema_version", 1},
          {"title", "Tilted block on a row of gaps, " + std::to_string(n) + " x " + std::to_string(n)},
          {"analysis", {{"type", "plane_strain"}}},
          {"nodes", nodes},
          {"materials", {{{"id", 1}, {"elastic", "isotropic"}, {"table", {{{"T", 0.0}, {"E", 30.0e6}, {"nu", 0.3}, {"alpha", 0.0}}}}}}},
          {"elements", elements},
          {"gaps", {{"initial_modulus", 100.0}, {"tensile_schedule", {50.0, 20.0, 10.0, 5.0, 2.0, 1.0}}, {"elements", gaps}}},
          {"constraints", constraints},
          {"loads", {{"pressures", pressures}}},
          {"solver", {{"max_iterations", 40}}}};
}

}  // namespace saasgaps::testing
