#include "web/plain_block.hpp"

#include <string>

namespace saasgaps::testing {

using nlohmann::json;

json plain_block_document(int n, int m) {
  json nodes = json::array(), elements = json::array(), constraints = json::array(), pressures = json::array();
  const double h = 1.0 / n;
  const auto id = [n](int i, int j) { return j * (n + 1) + i + 1; };
  for (int j = 0; j <= m; ++j) {
    for (int i = 0; i <= n; ++i) nodes.push_back({{"id", id(i, j)}, {"r", i * h}, {"z", j * h}});
  }
  for (int j = 0; j < m; ++j) {
    for (int i = 0; i < n; ++i) {
      elements.push_back({{"id", j * n + i + 1}, {"nodes", {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}}, {"material", 1}});
    }
  }
  for (int i = 0; i <= n; ++i) constraints.push_back({{"node", id(i, 0)}, {"r", 0.0}, {"z", 0.0}});
  for (int i = 0; i < n / 3; ++i) pressures.push_back({{"nodes", {id(i + 1, m), id(i, m)}}, {"normal", 1000.0}});
  return {{"schema_version", 1},
          {"title", "Plain block, " + std::to_string(n * m) + " elements"},
          {"units", {{"length", "in"}, {"force", "lbf"}, {"stress", "psi"}, {"temperature", "degF"}}},
          {"analysis", {{"type", "plane_strain"}}},
          {"nodes", nodes},
          {"materials", {{{"id", 1}, {"elastic", "isotropic"}, {"table", {{{"T", 0.0}, {"E", 30.0e6}, {"nu", 0.3}, {"alpha", 0.0}}}}}}},
          {"elements", elements},
          {"constraints", constraints},
          {"loads", {{"pressures", pressures}}}};
}

}  // namespace saasgaps::testing
