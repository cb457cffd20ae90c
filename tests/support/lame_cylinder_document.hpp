#pragma once
/// Lame's thick cylinder as a model document (a..b, plane strain along z as an axisymmetric slice
/// held in z, internal pressure on the bore), and Lame's bore displacement: the studies' tests
/// (tests/cli/study_command_test.cpp, tests/service/study_service_test.cpp).

#include <nlohmann/json.hpp>

namespace saasgaps::testing::lame_cylinder {

constexpr double a = 1.0, b = 2.0, nu = 0.3;
constexpr int radial = 8;

/// An axisymmetric slice of the cylinder a..b, one element high, held in z (plane strain along z),
/// under an internal pressure: node (i, j) has id 1 + i + (radial + 1) j.
inline nlohmann::json cylinder_document() {
  using nlohmann::json;
  const double h = (b - a) / radial;
  json nodes = json::array(), elements = json::array(), constraints = json::array();
  const auto id = [](int i, int j) { return 1 + i + (radial + 1) * j; };
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i <= radial; ++i) {
      nodes.push_back({{"id", id(i, j)}, {"r", a + i * h}, {"z", j * h}});
      constraints.push_back({{"node", id(i, j)}, {"z", 0.0}});
    }
  }
  for (int i = 0; i < radial; ++i) {
    elements.push_back({{"id", i + 1}, {"nodes", {id(i, 0), id(i + 1, 0), id(i + 1, 1), id(i, 1)}}, {"material", 1}});
  }
  return {{"schema_version", 1},
          {"title", "Lame thick cylinder"},
          {"analysis", {{"type", "axisymmetric"}}},
          {"nodes", nodes},
          {"materials", {{{"id", 1}, {"elastic", "isotropic"}, {"table", {{{"T", 0.0}, {"E", 30.0e6}, {"nu", nu}, {"alpha", 0.0}}}}}}},
          {"elements", elements},
          {"constraints", constraints},
          {"loads", {{"pressures", {{{"nodes", {id(0, 1), id(0, 0)}}, {"normal", 1000.0}}}}}}};
}

/// Lame's radial displacement of the bore in plane strain: u(a) = (1 + nu)/E [(1 - 2 nu) A a + B / a],
/// A = p a^2 / (b^2 - a^2), B = A b^2.
inline double lame_bore_displacement(double p, double E) {
  const double A = p * a * a / (b * b - a * a), B = A * b * b;
  return (1.0 + nu) / E * ((1.0 - 2.0 * nu) * A * a + B / a);
}

/// A study of the cylinder over the pressure p and the modulus E; outputs u_max (nodes.u_r, max)
/// and fz (reaction_sum.fz).
inline nlohmann::json study_document(const nlohmann::json& p_values, const nlohmann::json& e_values,
                                     const char* sampling = "grid") {
  using nlohmann::json;
  return {{"schema_version", 1},
          {"title", "thick cylinder, p and E"},
          {"model", cylinder_document()},
          {"parameters",
           {{{"name", "p"}, {"pointer", "/loads/pressures/0/normal"}, {"values", p_values}},
            {{"name", "E"}, {"pointer", "/materials/0/table/0/E"}, {"values", e_values}}}},
          {"sampling", sampling},
          {"outputs", {{{"name", "u_max"}, {"of", "nodes.u_r"}, {"reduce", "max"}},
                       {{"name", "fz"}, {"of", "reaction_sum.fz"}, {"reduce", "sum"}}}}};
}

}  // namespace saasgaps::testing::lame_cylinder
