// The VTU export on a hand-made result document: structure, cell types, and the values ParaView
// shows (check_vtu.py reads a real one back with meshio).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "io/vtu_writer.hpp"

namespace saasgaps::io {
namespace {

using nlohmann::json;

json triangle_and_gap() {
  const auto node = [](int id, double r, double z) {
    return json{{"id", id}, {"r", r}, {"z", z}, {"T", 70.0}, {"u_r", 0.1}, {"u_z", -0.25}};
  };
  return {{"status", "converged"},
          {"title", "a -- b"},
          {"analysis", "axisymmetric"},
          {"nodes", {node(10, 0.0, 0.0), node(20, 1.0, 0.0), node(30, 0.0, 1.0), node(40, 1.0, -0.01),
                     node(50, 0.0, -0.01)}},
          {"elements", {{{"id", 1}, {"nodes", {10, 20, 30}}, {"material", 7}, {"sigma_r", 0.1}, {"sigma_z", 2.0},
                         {"tau_rz", 3.0}, {"sigma_theta", 4.0}, {"sigma_1", 5.0}, {"sigma_2", 6.0}, {"angle", 7.0},
                         {"effective", 8.0}, {"eps_r", 1e-3}, {"eps_z", 2e-3}, {"gamma_rz", 3e-3},
                         {"eps_theta", 4e-3}, {"yield", true}, {"plastic_converged", false}}}},
          {"gaps", {{{"id", 2}, {"nodes", {50, 40, 20, 10}}, {"angle", 90.0}, {"eps_m", -1.02}, {"closure", 102.0},
                     {"modulus", 55.0}, {"sigma_m", -300.0}, {"state", "closed"}, {"converged", true}}}}};
}

std::string array_text(const std::string& vtu, const std::string& name) {
  const std::size_t start = vtu.find("Name=\"" + name + "\"");
  EXPECT_NE(start, std::string::npos) << name;
  const std::size_t open = vtu.find('>', start) + 1;
  const std::size_t close = vtu.find("</DataArray>", open);
  std::string text = vtu.substr(open, close - open);
  std::string squeezed;
  for (const char c : text) {
    if (c == '\n' || c == ' ') {
      if (!squeezed.empty() && squeezed.back() != ' ') squeezed += ' ';
    } else {
      squeezed += c;
    }
  }
  while (!squeezed.empty() && squeezed.back() == ' ') squeezed.pop_back();
  return squeezed;
}

TEST(VtuWriter, SolidsThenGapsWithTheirTypesAndData) {
  const std::string vtu = result_to_vtu(triangle_and_gap());
  EXPECT_NE(vtu.find("NumberOfPoints=\"5\" NumberOfCells=\"2\""), std::string::npos);
  EXPECT_NE(vtu.find("a - b"), std::string::npos) << "no '--' inside the XML comment";
  EXPECT_EQ(array_text(vtu, "Points"), "0 0 0 1 0 0 0 1 0 1 -0.01 0 0 -0.01 0");
  EXPECT_EQ(array_text(vtu, "connectivity"), "0 1 2 4 3 1 0");
  EXPECT_EQ(array_text(vtu, "offsets"), "3 7");
  EXPECT_EQ(array_text(vtu, "types"), "5 9");
  EXPECT_EQ(array_text(vtu, "displacement"), "0.1 -0.25 0 0.1 -0.25 0 0.1 -0.25 0 0.1 -0.25 0 0.1 -0.25 0");
  EXPECT_EQ(array_text(vtu, "node_id"), "10 20 30 40 50");
  EXPECT_EQ(array_text(vtu, "element_id"), "1 2");
  EXPECT_EQ(array_text(vtu, "is_gap"), "0 1");
  EXPECT_EQ(array_text(vtu, "material"), "7 0");
  EXPECT_EQ(array_text(vtu, "sigma_r"), "0.1 0");
  EXPECT_EQ(array_text(vtu, "principal_angle"), "7 0");
  EXPECT_EQ(array_text(vtu, "yield"), "1 0");
  EXPECT_EQ(array_text(vtu, "plastic_converged"), "0 1");
  EXPECT_EQ(array_text(vtu, "gap_closure"), "0 102");
  EXPECT_EQ(array_text(vtu, "gap_sigma_m"), "0 -300");
  EXPECT_EQ(array_text(vtu, "gap_state"), "-1 2");
  EXPECT_EQ(array_text(vtu, "gap_converged"), "-1 1");
}

TEST(VtuWriter, GapStateCodes) {
  EXPECT_EQ(vtu_gap_state_code("open"), 0);
  EXPECT_EQ(vtu_gap_state_code("partial"), 1);
  EXPECT_EQ(vtu_gap_state_code("closed"), 2);
  EXPECT_EQ(vtu_gap_state_code("overclosed"), 3);
  EXPECT_THROW(vtu_gap_state_code("ajar"), std::invalid_argument);
}

TEST(VtuWriter, RefusesResultsWithoutAMesh) {
  EXPECT_THROW(result_to_vtu({{"status", "failed"}, {"message", "singular"}, {"nodes", json::array()}}),
               std::invalid_argument);
  json old = triangle_and_gap();
  for (json& n : old["nodes"]) n.erase("r");
  EXPECT_THROW(result_to_vtu(old), std::invalid_argument);
  json dangling = triangle_and_gap();
  dangling["gaps"][0]["nodes"][0] = 99;
  EXPECT_THROW(result_to_vtu(dangling), std::invalid_argument);
}

}  // namespace
}  // namespace saasgaps::io
