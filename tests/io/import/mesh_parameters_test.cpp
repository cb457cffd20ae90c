// Geometry parameters through an assembly (docs/import.md): `mesh_parameters` set a .geo's
// DefineConstant values before the sandboxed mesher runs it, so a study reaches a dimension at
// /mesh_parameters/NAME; the file alone meshes with its defaults; a name the .geo does not declare,
// a value that is not a number, or parameters of a .msh are errors at their pointers.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/import/assembly_reader.hpp"
#include "solver/base/errors.hpp"
#include "support/temp_directory.hpp"

namespace saasgaps {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

/// A ring's section r in [1, 1 + wall], z in [0, 1]: wall and the element size are parameters, the
/// height is a plain assignment.
constexpr const char* ring_geo = R"(// the test geometry of mesh_parameters_test.cpp
DefineConstant[ wall = 0.5, lc = {0.25, Name "Parameters/lc"} ];
height = 1;
Point(1) = {1, 0, 0, lc}; Point(2) = {1 + wall, 0, 0, lc};
Point(3) = {1 + wall, height, 0, lc}; Point(4) = {1, height, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("ring") = {1};
Physical Curve("bottom") = {1};
)";

class MeshParameters : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(dir_ / "ring.geo") << ring_geo; }

  [[nodiscard]] static json assembly() {
    return {{"schema_version", 1},
            {"title", "ring"},
            {"mesh", "ring.geo"},
            {"analysis", {{"type", "axisymmetric"}}},
            {"materials", {{{"id", 1}, {"elastic", "isotropic"}, {"table", {{{"T", 0.0}, {"E", 1e7}, {"nu", 0.3}, {"alpha", 0.0}}}}}}},
            {"regions", {{{"group", "ring"}, {"material", 1}}}},
            {"constraints", {{{"group", "bottom"}, {"z", 0.0}}}}};
  }

  /// The largest r and the node count of the imported model.
  [[nodiscard]] std::pair<double, std::size_t> outer_radius(const json& a) const {
    const json model = io::import_assembly(a, dir_);
    double r = 0.0;
    for (const json& n : model["nodes"]) r = std::max(r, n["r"].get<double>());
    return {r, model["nodes"].size()};
  }

  [[nodiscard]] std::vector<InputIssue> issues(const json& a) const {
    try {
      (void)io::import_assembly(a, dir_);
    } catch (const ModelError& e) {
      return e.issues();
    }
    ADD_FAILURE() << "the import succeeded";
    return {};
  }

  testing::TempDirectory temp_{"mesh-parameters"};
  fs::path dir_ = temp_.path();
};

TEST_F(MeshParameters, SetTheGeometrysConstantsAndTheDefaultsHoldWithoutThem) {
  const auto [r_default, n_default] = outer_radius(assembly());
  EXPECT_DOUBLE_EQ(r_default, 1.5);

  json a = assembly();
  a["mesh_parameters"] = {{"wall", 0.25}};
  EXPECT_DOUBLE_EQ(outer_radius(a).first, 1.25);

  // The ONELAB form (a Name of its own) takes its value by the variable's name too; a finer size
  // gives more nodes on the same section.
  a["mesh_parameters"] = {{"wall", 0.5}, {"lc", 0.125}};
  const auto [r_fine, n_fine] = outer_radius(a);
  EXPECT_DOUBLE_EQ(r_fine, 1.5);
  EXPECT_GT(n_fine, 2 * n_default);

  // Empty: the defaults.
  a["mesh_parameters"] = json::object();
  EXPECT_EQ(outer_radius(a), std::make_pair(r_default, n_default));
}

TEST_F(MeshParameters, AnUndeclaredNameOrANonNumberIsAnErrorAtItsPointer) {
  json a = assembly();
  a["mesh_parameters"] = {{"wal", 0.25}, {"height", 2.0}, {"lc", "fine"}};
  const std::vector<InputIssue> found = issues(a);
  ASSERT_EQ(found.size(), 3u);
  // Members in the order nlohmann::json keeps them (by name).
  EXPECT_EQ(found[0].pointer, "/mesh_parameters/height");
  EXPECT_NE(found[0].detail.find("declares no parameter \"height\""), std::string::npos) << found[0].detail;
  EXPECT_NE(found[0].detail.find("it declares wall, lc"), std::string::npos) << found[0].detail;
  EXPECT_EQ(found[1].pointer, "/mesh_parameters/lc");
  EXPECT_NE(found[1].detail.find("finite number"), std::string::npos) << found[1].detail;
  EXPECT_EQ(found[2].pointer, "/mesh_parameters/wal");

  a["mesh_parameters"] = {{"wall", 0.25}};
  a["mesh"] = "ring.msh";
  std::ofstream(dir_ / "ring.msh") << "not read";
  const std::vector<InputIssue> msh = issues(a);
  ASSERT_EQ(msh.size(), 1u);
  EXPECT_EQ(msh[0].pointer, "/mesh_parameters");
  EXPECT_NE(msh[0].detail.find("meshed already"), std::string::npos) << msh[0].detail;

  a["mesh"] = "ring.geo";
  a["mesh_parameters"] = {1, 2};
  const std::vector<InputIssue> shape = issues(a);
  ASSERT_EQ(shape.size(), 1u);
  EXPECT_EQ(shape[0].pointer, "/mesh_parameters");
}

}  // namespace
}  // namespace saasgaps
