// `saasgaps probe RESULT.json --at R,Z` (issue 32): the recovered stresses at a point, each
// material's side at an interface, and the errors for a point outside the mesh or malformed.
#include "command_fixture.hpp"

#include <cmath>
#include <fstream>
#include <map>

#include "support/two_material_block.hpp"

namespace saasgaps::testing {
namespace {

using nlohmann::json;

class ProbeCommand : public CommandTest {
 protected:
  /// The quickstart block (2 x 2 elements, uniform sigma_z = -1000 psi, heated to 200 degF), or
  /// with `two_materials` support/two_material_block.hpp's (an interface at r = 1), solved.
  std::string solved_block(bool two_materials) const {
    const json model = two_materials ? two_material_block() : json::parse(read(example("quickstart-plane-strain-block.json")));
    std::ofstream(path("block.json")) << model.dump();
    const Outcome solved = saasgaps("solve " + path("block.json") + " -q -o " + path("block.result.json"));
    EXPECT_EQ(solved.exit_code, 0) << solved.err;
    return path("block.result.json");
  }
};

TEST_F(ProbeCommand, PrintsTheRecoveredStressesDisplacementAndTemperatureAtThePoint) {
  const std::string result = solved_block(false);
  const Outcome text = saasgaps("probe " + result + " --at 0.5,1.5");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("point (x, y) = (0.5, 1.5) in element 3 (material 1)"), std::string::npos) << text.out;
  for (const char* name : {"sigma_r (σx)", "sigma_z (σy)", "tau_rz (τxy)", "effective", "u_r (ux)", "temperature"}) {
    EXPECT_NE(text.out.find(name), std::string::npos) << name << " in\n" << text.out;
  }
  const Outcome as_json = saasgaps("probe " + result + " --at 0.5,1.5 --json");
  ASSERT_EQ(as_json.exit_code, 0) << as_json.err;
  const json probe = json::parse(as_json.out);
  EXPECT_EQ(probe["element"], 3);
  EXPECT_EQ(probe["stresses"], "recovered");
  EXPECT_TRUE(probe["sides"].empty());
  EXPECT_NEAR(probe["values"]["sigma_z"].get<double>(), -1000.0, 1e-6);  // the uniform pressure
  // Plane strain: sigma_theta = nu sigma_z - E alpha (200 - 70) = -300 - 25350 (docs/cli.md).
  EXPECT_NEAR(probe["values"]["sigma_theta"].get<double>(), -25650.0, 1e-6);
  EXPECT_NEAR(probe["values"]["temperature"].get<double>(), 200.0, 1e-12);
  // The strain is uniform, so u_r is linear in r from 0 at the held left edge: u_r(0.5) is half of
  // node 2's (r = 1).
  const json solved = json_of(result);
  EXPECT_NEAR(probe["values"]["u_r"].get<double>(), solved["nodes"][1]["u_r"].get<double>() / 2.0, 1e-12);

  const Outcome one = saasgaps("probe " + result + " --at 1.5,0.5 --field sigma_z --field effective,u_z --json");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const json fields = json::parse(one.out)["values"];
  EXPECT_EQ(fields.size(), 3U);
  EXPECT_TRUE(fields.contains("effective") && fields.contains("u_z"));
}

TEST_F(ProbeCommand, AtAnInterfaceEachMaterialKeepsItsOwnSide) {
  const std::string result = solved_block(true);
  const json solved = json_of(result);
  ASSERT_FALSE(solved["node_sides"].empty());
  std::map<std::pair<int, int>, double> side_theta;  // (node, material) -> sigma_theta
  for (const json& s : solved["node_sides"]) side_theta[{s["node"], s["material"]}] = s["sigma_theta"];
  // (1, 0.5): halfway between nodes 2 and 5 on the interface; each side linear along the edge.
  const Outcome r = saasgaps("probe " + result + " --at 1,0.5 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json probe = json::parse(r.out);
  EXPECT_EQ(probe["element"], 1);
  EXPECT_EQ(probe["material"], 1);
  ASSERT_EQ(probe["sides"].size(), 1U);
  EXPECT_EQ(probe["sides"][0]["material"], 2);
  EXPECT_EQ(probe["sides"][0]["element"], 2);
  for (const int material : {1, 2}) {
    const json& values = material == 1 ? probe["values"] : probe["sides"][0]["values"];
    const double expected = (side_theta.at({2, material}) + side_theta.at({5, material})) / 2.0;
    EXPECT_NEAR(values["sigma_theta"].get<double>(), expected, 1e-9 * std::abs(expected)) << material;
  }
  EXPECT_GT(std::abs(probe["values"]["sigma_theta"].get<double>() -
                     probe["sides"][0]["values"]["sigma_theta"].get<double>()), 100.0)
      << "the hotter material is compressed more out of plane";
  const Outcome text = saasgaps("probe " + result + " --at 1,0.5");
  EXPECT_NE(text.out.find("material 2's side (element 2):"), std::string::npos) << text.out;
}

TEST_F(ProbeCommand, APointOutsideTheMeshOrMalformedIsAClearError) {
  const std::string result = solved_block(false);
  const Outcome outside = saasgaps("probe " + result + " --at 5,-1");
  EXPECT_EQ(outside.exit_code, 1);
  EXPECT_NE(outside.err.find("(5, -1) lies in no solid element"), std::string::npos) << outside.err;
  const Outcome malformed = saasgaps("probe " + result + " --at 1x,2");
  EXPECT_EQ(malformed.exit_code, 1);
  EXPECT_NE(malformed.err.find("'1x' in '1x,2' is not a number"), std::string::npos) << malformed.err;
  const Outcome gap_field = saasgaps("probe " + result + " --at 1,1 --field closure");
  EXPECT_EQ(gap_field.exit_code, 1);
  EXPECT_NE(gap_field.err.find("'closure' is a gap field"), std::string::npos) << gap_field.err;
  const Outcome missing = saasgaps("probe " + result);
  EXPECT_EQ(missing.exit_code, 64) << "--at is required";
}

}  // namespace
}  // namespace saasgaps::testing
