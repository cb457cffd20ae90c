#pragma once
/// Model documents as text for the tests that hold the text readers (io/model/model_reader.hpp) to the
/// tree reader (tests/io/model/model_reader_test.cpp, tests/io/model/scan_model_reader_test.cpp): the example
/// files, their text, and two Models read from the same document compared value for value.
/// SAASGAPS_EXAMPLES_DIR is defined for every test program (tests/CMakeLists.txt).

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "solver/model/model.hpp"

namespace saasgaps::testing {

/// The JSON models of schemas/examples (not the assemblies), sorted.
inline std::vector<std::filesystem::path> example_models() {
  std::vector<std::filesystem::path> paths;
  for (const auto& entry : std::filesystem::directory_iterator(SAASGAPS_EXAMPLES_DIR)) {
    if (entry.path().extension() == ".json") paths.push_back(entry.path());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

inline std::string text_of(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream all;
  all << in.rdbuf();
  return all.str();
}

/// The Model read from text equals the Model read from its tree, value for value.
inline void expect_same_model(const Model& a, const Model& b) {
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  for (std::size_t i = 0; i < a.nodes.size(); ++i) {
    EXPECT_EQ(a.nodes[i].id, b.nodes[i].id);
    EXPECT_EQ(a.nodes[i].r, b.nodes[i].r);
    EXPECT_EQ(a.nodes[i].z, b.nodes[i].z);
  }
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (std::size_t i = 0; i < a.elements.size(); ++i) {
    EXPECT_EQ(a.elements[i].id, b.elements[i].id);
    EXPECT_EQ(a.elements[i].nodes, b.elements[i].nodes);
    EXPECT_EQ(a.elements[i].node_count, b.elements[i].node_count);
    EXPECT_EQ(a.elements[i].material, b.elements[i].material);
    EXPECT_EQ(a.elements[i].angle_deg, b.elements[i].angle_deg);
  }
  ASSERT_EQ(a.constraints.size(), b.constraints.size());
  for (std::size_t i = 0; i < a.constraints.size(); ++i) {
    EXPECT_EQ(a.constraints[i].node, b.constraints[i].node);
    EXPECT_EQ(a.constraints[i].u_r, b.constraints[i].u_r);
    EXPECT_EQ(a.constraints[i].u_z, b.constraints[i].u_z);
  }
  EXPECT_EQ(a.materials.size(), b.materials.size());
  EXPECT_EQ(a.loads.node_temperature, b.loads.node_temperature);
  EXPECT_EQ(a.loads.nodal_forces.size(), b.loads.nodal_forces.size());
  EXPECT_EQ(a.loads.pressures.size(), b.loads.pressures.size());
  EXPECT_EQ(a.gaps.has_value(), b.gaps.has_value());
  if (a.gaps && b.gaps) {
    EXPECT_EQ(a.gaps->elements.size(), b.gaps->elements.size());
  }
  // The third round's sections: contact surfaces and pairs, load steps, heat conduction.
  ASSERT_EQ(a.contact.has_value(), b.contact.has_value());
  if (a.contact) {
    ASSERT_EQ(a.contact->surfaces.size(), b.contact->surfaces.size());
    for (std::size_t i = 0; i < a.contact->surfaces.size(); ++i) {
      EXPECT_EQ(a.contact->surfaces[i].name, b.contact->surfaces[i].name);
      EXPECT_EQ(a.contact->surfaces[i].edges, b.contact->surfaces[i].edges);
    }
    ASSERT_EQ(a.contact->pairs.size(), b.contact->pairs.size());
    for (std::size_t i = 0; i < a.contact->pairs.size(); ++i) {
      EXPECT_EQ(a.contact->pairs[i].surfaces, b.contact->pairs[i].surfaces);
      EXPECT_EQ(a.contact->pairs[i].friction, b.contact->pairs[i].friction);
      EXPECT_EQ(a.contact->pairs[i].conductance.has_value(), b.contact->pairs[i].conductance.has_value());
    }
  }
  ASSERT_EQ(a.steps.size(), b.steps.size());
  for (std::size_t i = 0; i < a.steps.size(); ++i) {
    EXPECT_EQ(a.steps[i].name, b.steps[i].name);
    EXPECT_EQ(a.steps[i].increments, b.steps[i].increments);
    EXPECT_EQ(a.steps[i].loads.has_value(), b.steps[i].loads.has_value());
    ASSERT_EQ(a.steps[i].constraints.size(), b.steps[i].constraints.size());
    for (std::size_t k = 0; k < a.steps[i].constraints.size(); ++k) {
      EXPECT_EQ(a.steps[i].constraints[k].node, b.steps[i].constraints[k].node);
      EXPECT_EQ(a.steps[i].constraints[k].u_r, b.steps[i].constraints[k].u_r);
      EXPECT_EQ(a.steps[i].constraints[k].u_z, b.steps[i].constraints[k].u_z);
    }
  }
  ASSERT_EQ(a.thermal.has_value(), b.thermal.has_value());
  if (a.thermal) {
    EXPECT_EQ(a.thermal->type, b.thermal->type);
    ASSERT_EQ(a.thermal->boundary.size(), b.thermal->boundary.size());
    for (std::size_t i = 0; i < a.thermal->boundary.size(); ++i) {
      EXPECT_EQ(a.thermal->boundary[i].kind, b.thermal->boundary[i].kind);
      EXPECT_EQ(a.thermal->boundary[i].edges.size(), b.thermal->boundary[i].edges.size());
      EXPECT_EQ(a.thermal->boundary[i].value, b.thermal->boundary[i].value);
      EXPECT_EQ(a.thermal->boundary[i].ambient, b.thermal->boundary[i].ambient);
    }
  }
}

}  // namespace saasgaps::testing
