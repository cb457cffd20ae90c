// The shrink fit imported from a Gmsh geometry (schemas/examples/assemblies/ring-fit.geo, meshed
// in-process, gap elements generated between the facing arcs) meets Lame's contact pressure as the
// hand-made ring model does (ring_contact_test.cpp): every gap within 0.8 % of -p (the README and
// docs/import.md: "within 2 %"), every closure within the tolerance. The press fit imported from
// ring-press-fit.geo (two rings meshed on their own, an interference, gaps.method "exact": contact
// surfaces) meets Lame's interference pressure. A plane-strain quarter of the press fit meshed at
// second order ("order": 2: quad8 whose mid-side nodes Gmsh places on the arcs) imports its face
// pair as curved 3-node contact surfaces and meets Lame's pressure within 0.05 % on average.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <unistd.h>

#include "io/import/assembly_reader.hpp"
#include "io/model/model_reader.hpp"
#include "solver/analysis/analysis.hpp"
#include "support/lame_rings.hpp"

namespace saasgaps {
namespace {

TEST(ImportedRingContact, RingFitFromGeoMatchesLame) {
  const std::filesystem::path dir = std::filesystem::path(SAASGAPS_EXAMPLES_DIR) / "assemblies";
  std::ifstream in(dir / "ring-fit.assembly.json");
  ASSERT_TRUE(in);
  const Model m = io::read_model(io::import_assembly(nlohmann::json::parse(in), dir));
  ASSERT_EQ(m.gaps->elements.size(), 24u);
  testing::lame_rings::expect_contact(m, solve(m), 0.008);  // observed 7.26e-3 low, as the hand-made ring
}

TEST(ImportedRingContact, PressFitOnNonMatchingFacesMatchesLame) {
  const std::filesystem::path dir = std::filesystem::path(SAASGAPS_EXAMPLES_DIR) / "assemblies";
  std::ifstream in(dir / "ring-press-fit.assembly.json");
  ASSERT_TRUE(in);
  const Model m = io::read_model(io::import_assembly(nlohmann::json::parse(in), dir));
  // The exact face pair became contact surfaces (no gap elements) on faces whose nodes do not match.
  EXPECT_FALSE(m.gaps);
  ASSERT_TRUE(m.contact);
  ASSERT_EQ(m.contact->surfaces.size(), 2u);
  ASSERT_EQ(m.contact->pairs.size(), 1u);
  EXPECT_EQ(m.contact->surfaces[0].name, "hub_bore");
  EXPECT_EQ(m.contact->surfaces[1].name, "shaft_outside");
  std::array<std::set<double>, 2> heights;  // z of each face's nodes
  for (std::size_t k = 0; k < 2; ++k) {
    for (const auto& edge : m.contact->surfaces[k].edges) {
      for (const int n : edge) heights[k].insert(m.nodes[static_cast<std::size_t>(n)].z);
    }
  }
  ASSERT_GE(heights[0].size(), 3u);
  ASSERT_GE(heights[1].size(), 3u);
  EXPECT_EQ(heights[0].size(), 13u) << "docs/import.md: 13 nodes on the hub's bore";
  EXPECT_EQ(heights[1].size(), 9u) << "and 9 on the shaft";

  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  ASSERT_EQ(s.contact.size(), 1u);
  ASSERT_EQ(s.contact[0].points.size(), heights[0].size());  // a point per node of side A
  // The rings and the interference of ring-press-fit.geo.
  const double p = testing::lame_rings::plane_strain_interference_pressure({1.0, 1.5, 2.2, 30.0e6, 0.3, 10.0e6, 0.33},
                                                                           1.5e-4);
  EXPECT_NEAR(p, 282.73, 0.005);  // the figure the example's description quotes
  double worst = 0.0;
  for (const ContactPointResult& point : s.contact[0].points) {
    EXPECT_EQ(point.state, ContactPointState::stick);
    worst = std::max(worst, std::abs(point.pressure / p - 1.0));
  }
  std::printf("imported press fit: worst contact pressure error %.3g %%\n", 100.0 * worst);
  EXPECT_LT(worst, 0.005);  // observed 0.23 %
}

// The quarter press fit, plane strain, from a .geo meshed at second order: each ring 4 quad8 through
// its wall, 20 edges on the shaft's outside (side A) against 16 on the hub's bore, the interference
// 1.5e-4 between the two arcs; held on the symmetry axes. The issue's bar: the mean pressure within
// 0.05 % of Lame's, every point within 0.3 %.
TEST(ImportedRingContact, CurvedPressFitFromASecondOrderGeoMeetsLame) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("saasgaps-quad8-fit-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream geo(dir / "quarter-fit.geo");
    geo << "a1 = 1.0; b = 1.5; b2 = 2.2; d = 1.5e-4;\n"
           "Point(1) = {0, 0, 0};\n"
           "Point(2) = {a1, 0, 0}; Point(3) = {b + d/2, 0, 0}; Point(4) = {0, b + d/2, 0}; Point(5) = {0, a1, 0};\n"
           "Point(6) = {b - d/2, 0, 0}; Point(7) = {b2, 0, 0}; Point(8) = {0, b2, 0}; Point(9) = {0, b - d/2, 0};\n"
           "Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};\n"
           "Line(5) = {6, 7}; Circle(6) = {7, 1, 8}; Line(7) = {8, 9}; Circle(8) = {9, 1, 6};\n"
           "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
           "Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};\n"
           "Transfinite Curve {1, 3, 5, 7} = 5; Transfinite Curve {2, 4} = 21; Transfinite Curve {6, 8} = 17;\n"
           "Transfinite Surface {1, 2}; Recombine Surface {1, 2};\n"
           "Mesh.SecondOrderIncomplete = 1;\n"
           "Physical Surface(\"shaft\") = {1}; Physical Surface(\"hub\") = {2};\n"
           "Physical Curve(\"shaft_outside\") = {2}; Physical Curve(\"hub_bore\") = {8};\n"
           "Physical Curve(\"x_axis\") = {1, 5}; Physical Curve(\"y_axis\") = {3, 7};\n";
  }
  const nlohmann::json assembly = nlohmann::json::parse(R"({
    "schema_version": 1, "title": "quarter press fit at second order", "mesh": "quarter-fit.geo", "order": 2,
    "analysis": {"type": "plane_strain"},
    "materials": [{"id": 1, "elastic": "isotropic", "table": [{"T": 0, "E": 30.0e6, "nu": 0.3, "alpha": 0}]},
                  {"id": 2, "elastic": "isotropic", "table": [{"T": 0, "E": 10.0e6, "nu": 0.33, "alpha": 0}]}],
    "regions": [{"group": "shaft", "material": 1}, {"group": "hub", "material": 2}],
    "constraints": [{"group": "x_axis", "z": 0.0}, {"group": "y_axis", "r": 0.0}],
    "gaps": {"method": "exact", "pairs": [{"faces": ["shaft_outside", "hub_bore"]}]}
  })");
  const nlohmann::json document = io::import_assembly(assembly, dir);
  std::filesystem::remove_all(dir);
  const Model m = io::read_model(document);
  for (const Element& e : m.elements) ASSERT_EQ(e.type, ElementType::quad8);
  ASSERT_TRUE(m.contact);
  ASSERT_EQ(m.contact->surfaces.size(), 2u);
  EXPECT_EQ(m.contact->surfaces[0].name, "shaft_outside");
  EXPECT_EQ(m.contact->surfaces[0].edges.size(), 20u);
  EXPECT_EQ(m.contact->surfaces[1].edges.size(), 16u);

  const Solution s = solve(m);
  ASSERT_EQ(s.status, RunStatus::converged) << s.message;
  ASSERT_EQ(s.contact.size(), 1u);
  ASSERT_EQ(s.contact[0].points.size(), 41u);  // every node of the shaft's outside, mid-side nodes included
  const double p = testing::lame_rings::plane_strain_interference_pressure({1.0, 1.5, 2.2, 30.0e6, 0.3, 10.0e6, 0.33},
                                                                           1.5e-4);
  double sum = 0.0, worst = 0.0;
  for (const ContactPointResult& point : s.contact[0].points) {
    EXPECT_EQ(point.state, ContactPointState::stick);
    sum += point.pressure;
    worst = std::max(worst, std::abs(point.pressure / p - 1.0));
  }
  const double mean = sum / static_cast<double>(s.contact[0].points.size()) / p - 1.0;
  std::printf("second-order quarter press fit: mean pressure %+.4f %%, worst point %.4f %%\n", 100.0 * mean,
              100.0 * worst);
  // Observed -0.0009 % mean, 0.0962 % worst (the issue asks 0.05 % and 0.3 %).
  EXPECT_LT(std::abs(mean), 5e-5);
  EXPECT_LT(worst, 1.5e-3);
}

}  // namespace
}  // namespace saasgaps
